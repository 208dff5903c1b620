// config_file.cpp — see config_file.h.
#include "cli/config_file.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

#include "base/errors.h"
#include "base/input_file.h"

namespace wf {
namespace {

constexpr size_t kMaxConfigBytes = 1u << 20; // a config file holds a few dozen flags
constexpr size_t kMaxMessage = 200;          // the whole error line, "error: " aside
constexpr size_t kMaxQuoted = 40;            // a piece of the file quoted in it

// A piece of the file as an error may quote it: bytes outside printable ASCII
// as \xNN, cut to kMaxQuoted characters.
std::string excerpt(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (out.size() >= kMaxQuoted) return "'" + out + "...'";
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    return "'" + out + "'";
}

std::string clipped(std::string message) {
    if (message.size() > kMaxMessage) message = message.substr(0, kMaxMessage - 3) + "...";
    return message;
}

[[noreturn]] void refuse(const std::string& path, int line, const std::string& what) {
    throw InputError(clipped(path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what));
}

std::string trimmed(const std::string& text) {
    const size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// A bare TOML key, or one part of a dotted one: letters, digits, '-' and '_'.
bool is_bare_key(const std::string& key) {
    if (key.empty()) return false;
    for (unsigned char c : key)
        if (!std::isalnum(c) && c != '-' && c != '_' && c != '.') return false;
    return key.front() != '.' && key.back() != '.' && key.find("..") == std::string::npos;
}

// The line without its comment: '#' outside quotes to the end. Throws for a
// quote left open.
std::string without_comment(const std::string& path, int number, const std::string& line) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == '\\' && quote == '"') ++i;
            else if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '#') {
            return line.substr(0, i);
        }
    }
    if (quote) refuse(path, number, std::string("a quote (") + quote + ") is not closed on its line");
    return line;
}

// Checks the whole file as the subset of TOML a config holds, and returns the
// line of each key, by its full name ("spp", "render.spp").
std::map<std::string, int> check_lines(const std::string& path, const std::string& text) {
    // A binary file first, wherever its first control byte lies: its lines
    // before that may look like anything.
    for (size_t i = 0; i < text.size(); ++i)
        if (const unsigned char c = text[i]; c < 0x20 && c != '\t' && c != '\n' && c != '\r')
            refuse(path, 1 + int(std::count(text.begin(), text.begin() + i, '\n')),
                   "not a text file (byte " + excerpt(std::string(1, char(c))) + ")");
    std::map<std::string, int> lines;
    std::string section;
    std::istringstream in(text);
    int number = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++number;
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        const std::string line = trimmed(without_comment(path, number, raw));
        if (line.empty()) continue;
        if (line.front() == '[') {
            const std::string name = line.size() < 3 ? "" : trimmed(line.substr(1, line.size() - 2));
            if (line.back() != ']' || line[1] == '[' || !is_bare_key(name))
                refuse(path, number, excerpt(line) + " is not a [section] heading");
            section = name;
            continue;
        }
        const size_t equals = line.find('=');
        if (equals == std::string::npos) refuse(path, number, excerpt(line) + " is not 'name = value'");
        std::string key = trimmed(line.substr(0, equals));
        if (key.size() >= 2 && (key.front() == '"' || key.front() == '\'') && key.back() == key.front())
            key = key.substr(1, key.size() - 2);
        if (!is_bare_key(key)) refuse(path, number, excerpt(key) + " is not a flag name");
        const std::string value = trimmed(line.substr(equals + 1));
        if (value.empty()) refuse(path, number, "'" + key + "' has no value");
        if (value.front() == '[' || value.front() == '{')
            refuse(path, number, "'" + key + "' takes one value, not " + (value.front() == '[' ? "an array" : "a table"));
        if ((value.front() == '"' || value.front() == '\'') && value.find(value.front(), 1) != value.size() - 1)
            refuse(path, number, "'" + key + "': text after the quoted value, or a multi-line string");
        const std::string full = section.empty() ? key : section + "." + key;
        if (const auto [it, fresh] = lines.emplace(full, number); !fresh)
            refuse(path, number, "'" + full + "' is given twice (first on line " + std::to_string(it->second) + ")");
    }
    return lines;
}

std::string read_text(const std::string& path) {
    require_regular_file(path, "config file");
    std::ifstream in(path, std::ios::binary);
    std::string text;
    if (in) {
        std::ostringstream bytes;
        bytes << in.rdbuf();
        text = bytes.str();
    }
    if (!in) refuse(path, 0, "cannot read the config file");
    if (text.size() > kMaxConfigBytes) refuse(path, 0, "larger than 1 MiB; a config file holds a few flags");
    return text;
}

} // namespace

std::string config_path(int argc, const char** argv) {
    for (int i = 2; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--config" && i + 1 < argc) return argv[i + 1];
        if (word.rfind("--config=", 0) == 0) return word.substr(9);
    }
    return "";
}

std::vector<ConfigFlag> read_config_flags(const CLI::App& render, const std::string& path) {
    const std::string text = read_text(path);
    const std::map<std::string, int> lines = check_lines(path, text);
    std::vector<CLI::ConfigItem> items;
    try {
        std::istringstream in(text);
        items = CLI::ConfigTOML().from_config(in);
    } catch (const CLI::Error& e) {
        refuse(path, 0, std::string("cannot read the config file (") + e.what() + ")");
    }
    std::vector<ConfigFlag> flags;
    std::map<std::string, int> flag_lines; // `spp` and `render.spp` are one flag
    for (const CLI::ConfigItem& item : items) {
        if (item.name == "++" || item.name == "--") continue; // CLI11's markers of a section's start and end
        // `[ render ]` is `[render]`: TOML allows the spaces, CLI11 keeps them.
        std::string full = trimmed(item.name);
        for (auto parent = item.parents.rbegin(); parent != item.parents.rend(); ++parent)
            full = trimmed(*parent) + "." + full;
        const auto where = lines.find(full);
        const int line = where == lines.end() ? 0 : where->second;
        const std::string name = excerpt(full);
        const bool ours = item.parents.empty() || (item.parents.size() == 1 && trimmed(item.parents[0]) == "render");
        const std::string flag = "--" + item.name;
        if (!ours || item.name == "config" || !render.get_option_no_throw(flag))
            refuse(path, line, name + " is not a render flag");
        if (item.inputs.size() != 1) refuse(path, line, name + " needs one value");
        if (const auto [it, fresh] = flag_lines.emplace(flag, line); !fresh)
            refuse(path, line, name + " gives " + flag + " again (first on line " + std::to_string(it->second) + ")");
        const std::string& value = item.inputs[0];
        if (render.get_option(flag)->get_expected_min() == 0) { // a flag: true or false
            if (value != "true" && value != "false") refuse(path, line, name + " is true or false, not " + excerpt(value));
            if (value == "true") flags.push_back({flag, flag, line});
        } else {
            flags.push_back({flag + "=" + value, flag, line});
        }
    }
    return flags;
}

std::string config_error(const std::string& path, const std::vector<ConfigFlag>& flags, const std::string& error) {
    // The flag the error names: "--flag" followed by ':' or a space, so that
    // --env is not taken for --env-scale.
    int line = 0;
    for (const ConfigFlag& f : flags)
        for (size_t at = error.find(f.flag); at != std::string::npos; at = error.find(f.flag, at + 1)) {
            const size_t end = at + f.flag.size();
            if (end == error.size() || error[end] == ':' || error[end] == ' ') line = f.line;
        }
    return clipped(path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + error);
}

} // namespace wf
