// output_files.h — the files a render writes (image, partial render, CSV
// report, statistics): every path is checked before any work starts, and each
// file is written whole or not at all, through a temporary beside it that is
// renamed over it and removed on any failure.
#pragma once

#include <filesystem>
#include <string>

namespace wf {

// Whether a new file can be made in `folder`, tried with a probe file that is
// removed at once.
bool folder_takes_new_files(const std::filesystem::path& folder);

// Throws InputError naming `path` unless a file can be written there: its
// folder exists and takes a new file, the path is not a folder, and a file
// already there may be replaced.
void check_can_write_file(const std::string& path);

// The temporary an atomic write of `path` goes through: hidden, beside it
// (so the rename stays on one file system), with its extension (which picks
// an image's format), and unique to this process.
std::filesystem::path temporary_beside(const std::string& path);

// Renames the written `temporary` over `path`; on failure removes it and
// throws InputError naming `path`.
void replace_with(const std::filesystem::path& temporary, const std::string& path);

// Writes `contents` to `path` atomically. Throws InputError naming `path`.
void write_file_atomically(const std::string& path, const std::string& contents);

} // namespace wf
