// input_file.cpp — see input_file.h.
#include "base/input_file.h"

#include <filesystem>

#include "base/errors.h"

namespace wf {

std::string not_a_regular_file(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error); // follows links
    switch (status.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return "no such file";
    case fs::file_type::directory: return "a directory, not a regular file";
    case fs::file_type::fifo: return "a FIFO, not a regular file";
    case fs::file_type::socket: return "a socket, not a regular file";
    case fs::file_type::block:
    case fs::file_type::character: return "a device, not a regular file";
    default: return error ? "cannot read (" + error.message() + ")" : "not a regular file";
    }
}

void require_regular_file(const std::string& path, const std::string& what) {
    if (const std::string why = not_a_regular_file(path); !why.empty())
        throw InputError(path + ": " + what + ": " + why);
}

} // namespace wf
