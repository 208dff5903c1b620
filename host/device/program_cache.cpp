// program_cache.cpp — entries are "<16 hex digits of FNV-1a 64 of the key>.clbin":
// the magic line, the key's length and bytes, then the binary.
#include "device/program_cache.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <unistd.h>

namespace wf {
namespace {

constexpr char kMagic[] = "wavefront program cache 1\n";
constexpr const char* kExtension = ".clbin";

uint64_t fnv1a(const std::string& text) {
    uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

} // namespace

std::optional<std::filesystem::path> ProgramCache::default_directory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "wavefront";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "wavefront";
    return std::nullopt;
}

std::string program_cache_key(const DeviceInfo& device, const std::string& options, const std::string& source) {
    return device.platform + "\n" + device.name + "\n" + device.version + "\n" + device.driver + "\n" + options +
           "\n" + source;
}

std::filesystem::path ProgramCache::entry_path(const std::string& key) const {
    std::ostringstream name;
    name << std::hex << std::setw(16) << std::setfill('0') << fnv1a(key) << kExtension;
    return directory_ / name.str();
}

std::optional<std::vector<unsigned char>> ProgramCache::load(const std::string& key) const {
    std::ifstream in(entry_path(key), std::ios::binary);
    if (!in) return std::nullopt;
    std::string magic(sizeof kMagic - 1, '\0');
    uint64_t key_size = 0, binary_size = 0;
    if (!in.read(magic.data(), std::streamsize(magic.size())) || magic != kMagic) return std::nullopt;
    if (!in.read(reinterpret_cast<char*>(&key_size), sizeof key_size) || key_size != key.size()) return std::nullopt;
    std::string stored(key_size, '\0');
    if (!in.read(stored.data(), std::streamsize(key_size)) || stored != key) return std::nullopt;
    if (!in.read(reinterpret_cast<char*>(&binary_size), sizeof binary_size) || binary_size == 0 ||
        binary_size > (1ull << 30))
        return std::nullopt;
    std::vector<unsigned char> binary(binary_size);
    if (!in.read(reinterpret_cast<char*>(binary.data()), std::streamsize(binary_size))) return std::nullopt;
    return binary;
}

void ProgramCache::store(const std::string& key, const std::vector<unsigned char>& binary) const {
    std::error_code error;
    std::filesystem::create_directories(directory_, error);
    const std::filesystem::path target = entry_path(key);
    std::filesystem::path temporary = target;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        const uint64_t key_size = key.size(), binary_size = binary.size();
        out.write(kMagic, sizeof kMagic - 1);
        out.write(reinterpret_cast<const char*>(&key_size), sizeof key_size);
        out.write(key.data(), std::streamsize(key.size()));
        out.write(reinterpret_cast<const char*>(&binary_size), sizeof binary_size);
        out.write(reinterpret_cast<const char*>(binary.data()), std::streamsize(binary.size()));
        if (!out) {
            std::filesystem::remove(temporary, error);
            return;
        }
    }
    std::filesystem::rename(temporary, target, error);
    if (error) std::filesystem::remove(temporary, error);
}

size_t ProgramCache::clear() const {
    size_t removed = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory_, error))
        if (entry.path().extension() == kExtension && std::filesystem::remove(entry.path(), error)) ++removed;
    return removed;
}

} // namespace wf
