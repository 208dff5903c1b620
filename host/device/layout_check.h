// layout_check.h — the start-up check that host and device agree on the
// layout of every shared struct (include/wavefront/layout_fields.h).
#pragma once

#include <string>

#include "device/opencl_device.h"

namespace wf {

// Throws DeviceError naming the first struct or member whose size or offset
// differs between this compiler and the device's. Returns the probe's build
// warning (KernelProgram::warning), if it has one.
std::string check_shared_layouts(const OpenClDevice& device);

} // namespace wf
