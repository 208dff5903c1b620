// cli.h — the command line: `wavefront render SCENE [flags]`, `wavefront
// devices`, `wavefront cache warm|clear`, `--help` on each, `--version`. Every
// flag value is checked here; a bad one is an InputError that names the
// command, the flag and the value. Render's flags fill the render request
// (session/render_options.h); run_command.h runs what was asked.
#pragma once

#include <string>
#include <vector>

#include "session/kernel_cache.h"
#include "session/render_options.h"

namespace wf {

enum class Command { Render, Devices, Help, Version, CacheWarm, CacheClear };

struct CommandLine {
    Command command = Command::Help;
    RenderOptions render;
    CacheOptions cache;
    std::string help; // the text to print for Command::Help
};

CommandLine parse_command_line(int argc, const char** argv);

// A flag of `wavefront render` as the command line declares it, for front ends
// that must offer the same flags (the Python module's keywords).
struct FlagInfo {
    std::string name;        // "pool-size"
    std::string type;        // its kind and check, as --help shows them: "UINT:in 1 to 67108864", "FILE"
    std::string help;        // one line, ending "(default: ...)"
    bool takes_value = true; // false: a flag alone (--quiet)
};
std::vector<FlagInfo> render_flags();

} // namespace wf
