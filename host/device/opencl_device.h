// opencl_device.h — finding and opening an OpenCL device: the list that
// `wavefront devices` prints, the choice that `--device` makes, and the context
// and profiling queue every later step uses.
#pragma once

#include <string>
#include <vector>

#include <CL/opencl.hpp>

namespace wf {

struct DeviceInfo {
    int index = 0; // position in the list over all platforms
    std::string platform;
    std::string name;
    std::string type; // "cpu", "gpu", "accelerator" or "other"
    std::string version;
    std::string driver;
    unsigned compute_units = 0;
    unsigned long long global_memory = 0;
    unsigned long long max_allocation = 0;
    unsigned native_float_width = 1; // floats in one of its vector registers (8 for AVX2, 16 for AVX-512)
    unsigned long long global_cache = 0; // bytes of its global memory cache (a CPU's last level; 0: unknown)
    cl::Device device;
};

// Every device of every platform. Throws DeviceError when there is no OpenCL
// platform at all, naming the packages that provide one.
std::vector<DeviceInfo> list_devices();

// `spec` is empty (the first GPU, else the first device), an index from
// list_devices(), or a type: "cpu", "gpu". Throws InputError when nothing matches.
DeviceInfo choose_device(const std::string& spec);
// `spec` is "all", or one or more of choose_device()'s, separated by commas
// ("0,2", "gpu,cpu"). Throws InputError when one matches nothing or a device
// is named twice.
std::vector<DeviceInfo> choose_devices(const std::string& spec);

struct OpenClDevice {
    DeviceInfo info;
    cl::Context context;
    cl::CommandQueue queue; // in order, with profiling enabled
};

OpenClDevice open_device(const std::string& spec);
std::vector<OpenClDevice> open_devices(const std::string& spec);

} // namespace wf
