// version_text.cpp — built into the executable alone: build_info.h changes
// with every commit, and the core library should not recompile for it.
#include "cli/version_text.h"

#include <sstream>
#include <vector>

#include <CL/opencl.hpp>
#include <OpenImageIO/imageio.h>

#include "build_info.h"

namespace wf {

std::string version_text() {
    std::ostringstream text;
    text << "wavefront " << WF_VERSION << "\n"
         << "commit     " << WF_COMMIT << "\n"
         << "build      " << WF_BUILD_TYPE << "\n"
         << "OpenCL     headers for " << CL_HPP_TARGET_OPENCL_VERSION / 100 << "."
         << CL_HPP_TARGET_OPENCL_VERSION / 10 % 10 << " (kernels are OpenCL C 1.2)\n";
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error&) {
    }
    if (platforms.empty()) text << "platform   none found\n";
    for (const cl::Platform& p : platforms) // PoCL's names its own release: "OpenCL 3.0 PoCL 3.1+debian ..."
        text << "platform   " << p.getInfo<CL_PLATFORM_NAME>() << ": " << p.getInfo<CL_PLATFORM_VERSION>() << "\n";
    text << "OpenImageIO " << OIIO::openimageio_version() / 10000 << "." << OIIO::openimageio_version() / 100 % 100
         << "." << OIIO::openimageio_version() % 100 << "\n";
    return text.str();
}

} // namespace wf
