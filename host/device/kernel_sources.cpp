// kernel_sources.cpp — resolves `#include "..."` in the embedded kernel files,
// so the program handed to the OpenCL compiler is one self-contained string:
// no include paths on the device, and the exact text can key a binary cache.
#include "device/kernel_sources.h"

#include <set>
#include <sstream>

#include "base/errors.h"

namespace wf {
namespace {

const char* find_embedded(const std::string& path) {
    for (const EmbeddedFile& f : embedded_kernel_files())
        if (path == f.path) return f.text;
    throw DeviceError("kernel source '" + path + "' is not embedded in this build");
}

// A header is expanded once, as its include guard would have it; a .inc file
// (code written once for any lane width, kernels/lanes/lanes.h) at every
// #include, once per width.
bool expanded_once(const std::string& path) { return path.size() < 4 || path.compare(path.size() - 4, 4, ".inc") != 0; }

void expand_into(const std::string& path, std::set<std::string>& seen, std::ostringstream& out) {
    if (expanded_once(path) && !seen.insert(path).second) return;
    std::istringstream in(find_embedded(path));
    std::string line;
    int line_number = 0;
    out << "#line 1 \"" << path << "\"\n";
    while (std::getline(in, line)) {
        ++line_number;
        const size_t hash = line.find_first_not_of(" \t");
        const bool is_include = hash != std::string::npos && line.compare(hash, 8, "#include") == 0;
        const size_t open = is_include ? line.find('"') : std::string::npos;
        const size_t close = open != std::string::npos ? line.find('"', open + 1) : std::string::npos;
        if (close == std::string::npos) {
            out << line << '\n';
            continue;
        }
        expand_into(line.substr(open + 1, close - open - 1), seen, out);
        out << "#line " << line_number + 1 << " \"" << path << "\"\n";
    }
}

} // namespace

std::string expand_kernel_source(const std::string& path) {
    std::set<std::string> seen;
    std::ostringstream out;
    expand_into(path, seen, out);
    return out.str();
}

} // namespace wf
