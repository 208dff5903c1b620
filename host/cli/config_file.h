// config_file.h — render's `--config FILE`: flags from a TOML file, one
// `name = value` a line, at the top or under [render]. Each line is checked
// before CLI11 reads the file (ConfigTOML), so that every error names the
// file and the line, in one line of at most 200 characters: a binary file, an
// unclosed quote, a value nested thousands deep or an empty one is refused
// as such, and a flag's bad value is traced back to the line that gave it.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace wf {

// One flag the file gives: the argument it becomes (`--spp=64`, `--quiet`)
// and the line it came from.
struct ConfigFlag {
    std::string argument;
    std::string flag; // "--spp"
    int line = 0;
};

// The file named by render's --config (`--config FILE` or `--config=FILE`),
// or "" when there is none.
std::string config_path(int argc, const char** argv);

// The file's flags in its order, to be placed before the command line's own,
// which then win (every render flag keeps the last value given). Throws
// InputError "FILE:LINE: what is wrong" for a file that is not a regular one,
// a line that is no `name = value`, `[section]` or comment, or a key that no
// render flag has.
std::vector<ConfigFlag> read_config_flags(const CLI::App& render, const std::string& path);

// `error`, a flag's error from CLI11 ("render: --spp: 0 is not in ..."),
// prefixed by the file and line of the flag it names: "FILE:3: render: ...".
std::string config_error(const std::string& path, const std::vector<ConfigFlag>& flags, const std::string& error);

} // namespace wf
