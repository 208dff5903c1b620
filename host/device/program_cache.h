// program_cache.h — compiled kernel programs kept on disk, so a second render
// of a scene with the same features skips the compiler. An entry is keyed by
// everything that decides the binary: the kernel source after its includes,
// the build options (the feature defines among them), and the device, its
// OpenCL version and its driver version. The key is stored whole in the
// entry and compared exactly on load, so a stale or colliding entry is never
// run: it is rebuilt from source and replaced. Entries are written to a
// temporary file and renamed, so a crash never leaves a torn one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "device/opencl_device.h"

namespace wf {

class ProgramCache {
public:
    explicit ProgramCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

    // $XDG_CACHE_HOME/wavefront, else $HOME/.cache/wavefront; nullopt with neither.
    static std::optional<std::filesystem::path> default_directory();

    // The binary stored under `key`, if there is one and its key matches.
    std::optional<std::vector<unsigned char>> load(const std::string& key) const;
    // Stores `binary` under `key`; a failure to write only costs the next compile.
    void store(const std::string& key, const std::vector<unsigned char>& binary) const;
    // Removes every entry; returns how many.
    size_t clear() const;

    const std::filesystem::path& directory() const { return directory_; }

private:
    std::filesystem::path entry_path(const std::string& key) const;
    std::filesystem::path directory_;
};

// The key of a program: device, driver, options and the expanded source.
std::string program_cache_key(const DeviceInfo& device, const std::string& options, const std::string& source);

} // namespace wf
