// kernel_sources.h — the kernels' OpenCL C source, compiled into the
// executable by cmake/embed_kernels.cmake and assembled here into one
// translation unit per program.
#pragma once

#include <string>
#include <vector>

namespace wf {

struct EmbeddedFile {
    const char* path; // relative to kernels/ or include/, e.g. "stages/shade.h"
    const char* text;
};

const std::vector<EmbeddedFile>& embedded_kernel_files();

// The source of `path` with every `#include "..."` replaced by the named
// embedded file, each file at most once (so include guards are optional).
// Throws DeviceError if a file is not embedded.
std::string expand_kernel_source(const std::string& path);

} // namespace wf
