// oidn_api.h — the part of Intel Open Image Denoise's C API that denoiser.cpp
// calls, declared here because Debian 12 packages no OIDN headers: the
// library (PyPI's pyoidn wheel bundles libOpenImageDenoise.so.2) is opened
// with dlopen and these are the types of the symbols looked up in it. They
// match OpenImageDenoise/oidn.h of OIDN 2.x (checked against 2.5.1, the
// version pyoidn 2.5.1.0 bundles); the 2.x ABI keeps them.
#pragma once

#include <cstddef>

namespace wf::oidn {

typedef struct OIDNDeviceImpl* OIDNDevice;
typedef struct OIDNFilterImpl* OIDNFilter;

enum OIDNDeviceType { OIDN_DEVICE_TYPE_DEFAULT = 0, OIDN_DEVICE_TYPE_CPU = 1 };
enum OIDNError { OIDN_ERROR_NONE = 0 };
enum OIDNFormat { OIDN_FORMAT_FLOAT3 = 3 };

using NewDevice = OIDNDevice (*)(OIDNDeviceType type);
using CommitDevice = void (*)(OIDNDevice device);
using ReleaseDevice = void (*)(OIDNDevice device);
using GetDeviceError = OIDNError (*)(OIDNDevice device, const char** outMessage);
using NewFilter = OIDNFilter (*)(OIDNDevice device, const char* type);
using SetSharedFilterImage = void (*)(OIDNFilter filter, const char* name, void* devPtr, OIDNFormat format,
                                      size_t width, size_t height, size_t byteOffset, size_t pixelByteStride,
                                      size_t rowByteStride);
using SetFilterBool = void (*)(OIDNFilter filter, const char* name, bool value);
using CommitFilter = void (*)(OIDNFilter filter);
using ExecuteFilter = void (*)(OIDNFilter filter);
using ReleaseFilter = void (*)(OIDNFilter filter);

} // namespace wf::oidn
