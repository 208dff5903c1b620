// output_files.cpp — a probe file tells whether a folder takes new files,
// whoever the user is (access() says yes to root even on a read-only mount);
// a file already there must be one the user may replace.
#include "base/output_files.h"

#include <fstream>

#include <unistd.h>

#include "base/errors.h"

namespace wf {

bool folder_takes_new_files(const std::filesystem::path& folder) {
    const std::filesystem::path probe = folder / (".wavefront-probe-" + std::to_string(::getpid()));
    if (!std::ofstream(probe)) return false;
    std::error_code ignored;
    std::filesystem::remove(probe, ignored);
    return true;
}

void check_can_write_file(const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : ".";
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw InputError(path + ": no such folder " + folder.string());
    if (fs::is_directory(target, ec)) throw InputError(path + ": is a folder, not a file");
    if (fs::exists(target, ec) && ::access(path.c_str(), W_OK) != 0)
        throw InputError(path + ": the file there is read-only");
    if (!folder_takes_new_files(folder)) throw InputError(path + ": cannot write in " + folder.string());
}

std::filesystem::path temporary_beside(const std::string& path) {
    const std::filesystem::path target(path);
    return target.parent_path() /
           ("." + target.stem().string() + ".writing-" + std::to_string(::getpid()) + target.extension().string());
}

void replace_with(const std::filesystem::path& temporary, const std::string& path) {
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (!error) return;
    std::filesystem::remove(temporary, error);
    throw InputError(path + ": write failed (cannot rename the written file)");
}

void write_file_atomically(const std::string& path, const std::string& contents) {
    const std::filesystem::path temporary = temporary_beside(path);
    std::ofstream out(temporary, std::ios::binary);
    out << contents;
    out.close();
    if (!out) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw InputError(path + ": write failed");
    }
    replace_with(temporary, path);
}

} // namespace wf
