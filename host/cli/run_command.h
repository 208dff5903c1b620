// run_command.h — the command dispatch of `wavefront` and of
// `python -m wavefront`, one function for both: parse the command line, run
// the command, and turn what happened into the exit status:
//   0 success · 1 the machine failed (no OpenCL device, a kernel that will not
//   build) · 2 the input is at fault (a scene, a flag, an output path) ·
//   128 + signal: a render stopped by Ctrl-C or SIGTERM, its image written.
// Every failure is one line on stderr that names the thing at fault.
#pragma once

#include <string>

namespace wf {

// What `--version` prints (version_text.h), given by the caller: it is built
// into each program alone, not into the library.
using VersionText = std::string (*)();

// Runs `argv` (argv[0] the program, unread) as the `wavefront` program does,
// printing on std::cout and std::cerr; returns the exit status.
int run_command_line(int argc, const char** argv, VersionText version_text);

} // namespace wf
