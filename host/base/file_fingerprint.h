// file_fingerprint.h — what identifies a file's contents wherever it lies:
// --resume compares the scene a partial render was made from by this, not by
// the path typed.
#pragma once

#include <string>

namespace wf {

// A 64-bit fingerprint of the file's bytes, as 16 hex digits. Throws InputError
// naming `path` when it cannot be read.
std::string file_fingerprint(const std::string& path);

} // namespace wf
