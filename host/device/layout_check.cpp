// layout_check.cpp — runs kernels/layout_probe.cl and compares its answers
// with sizeof/offsetof on the host, entry by entry, in the same macro order.
#include "device/layout_check.h"

#include <cstddef>
#include <string>
#include <vector>

#include "base/errors.h"
#include "device/kernel_program.h"
#include "wavefront/layout_fields.h"
#include "wavefront/render_params.h"
#include "wavefront/scene_types.h"

namespace wf {

std::string check_shared_layouts(const OpenClDevice& device) {
    std::vector<uint32_t> host;
    std::vector<std::string> names;
#define WF_HOST_SIZE(S)                                                                         \
    host.push_back(static_cast<uint32_t>(sizeof(S)));                                            \
    names.push_back("sizeof(" #S ")");
#define WF_HOST_OFFSET(S, m)                                                                    \
    host.push_back(static_cast<uint32_t>(offsetof(S, m)));                                       \
    names.push_back("offsetof(" #S ", " #m ")");
    WF_LAYOUT_STRUCTS(WF_HOST_SIZE)
    WF_LAYOUT_MEMBERS(WF_HOST_OFFSET)
#undef WF_HOST_SIZE
#undef WF_HOST_OFFSET

    const KernelProgram probe = build_kernel_program(device, "layout_probe.cl");
    cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, host.size() * sizeof(uint32_t));
    cl::Kernel kernel(probe.program, "layout_probe");
    kernel.setArg(0, out);
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NDRange(1));
    std::vector<uint32_t> on_device(host.size());
    device.queue.enqueueReadBuffer(out, CL_TRUE, 0, host.size() * sizeof(uint32_t), on_device.data());
    for (size_t i = 0; i < host.size(); ++i)
        if (host[i] != on_device[i])
            throw DeviceError("shared struct layout differs on " + device.info.name + ": " + names[i] +
                              " is " + std::to_string(host[i]) + " on the host, " +
                              std::to_string(on_device[i]) + " on the device");
    return probe.warning;
}

} // namespace wf
