// version_text.h — what `wavefront --version` prints: the release, the commit
// and build type it was built from, and the versions of what it runs on (the
// OpenCL headers and platforms, PoCL among them, and OpenImageIO), which
// decide what a bug report can be reproduced with.
#pragma once

#include <string>

namespace wf {

std::string version_text();

} // namespace wf
