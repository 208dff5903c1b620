// input_file.h — the check every file the renderer reads passes first. Opening a
// FIFO waits for a writer, forever; a device or a socket may never end; a
// directory is no image. So only a regular file (or a link to one) is opened,
// and the check itself opens nothing: it reads the file's status.
#pragma once

#include <string>

namespace wf {

// Why `path` cannot be read as a file ("no such file", "a FIFO, not a regular
// file", ...), or "" when it names a regular file.
std::string not_a_regular_file(const std::string& path);

// Throws InputError "PATH: WHAT: why" unless `path` names a regular file;
// `what` says what the file was to be ("the reference image").
void require_regular_file(const std::string& path, const std::string& what);

} // namespace wf
