// file_fingerprint.cpp — OpenImageIO's FarmHash fingerprint (stable across
// platforms and releases, as a fingerprint must be) of the whole file: a
// glTF's JSON, or a GLB such as DamagedHelmet's 3.8 MB, in milliseconds.
#include "base/file_fingerprint.h"

#include <cstdio>
#include <fstream>
#include <iterator>

#include <OpenImageIO/hash.h>

#include "base/errors.h"
#include "base/input_file.h"

namespace wf {

std::string file_fingerprint(const std::string& path) {
    require_regular_file(path, "file");
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in && !in.eof()) throw InputError(path + ": cannot read");
    char text[17];
    std::snprintf(text, sizeof text, "%016llx",
                  static_cast<unsigned long long>(OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size())));
    return text;
}

} // namespace wf
