// kernel_cache.h — the compiled kernels kept on disk (device/program_cache.h)
// as a user sees them: where they are, `wavefront cache warm`, which compiles
// the kernels scenes need before any render waits for them, and
// `wavefront cache clear`.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace wf {

// `wavefront cache warm|clear`.
struct CacheOptions {
    std::string directory;           // --cache-dir, else the default (program_cache.h)
    std::string device;              // for warm
    std::vector<std::string> scenes; // for warm
};

// The program cache's directory: `requested`, else the default; empty with neither.
std::string cache_directory(const std::string& requested);

// `wavefront cache warm`: compiles the kernels each scene needs into the cache.
void warm_cache(const CacheOptions& options, std::ostream& out);

// `wavefront cache clear`.
void clear_cache(const CacheOptions& options, std::ostream& out);

} // namespace wf
