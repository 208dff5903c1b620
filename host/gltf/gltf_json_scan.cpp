// gltf_json_scan.cpp — see gltf_json_scan.h. nlohmann's SAX parser keeps its
// own stack, so the scan itself does not recurse, however deep the JSON.
#include "gltf/gltf_json_scan.h"

#include <nlohmann/json.hpp>

#include "gltf/gltf_diagnostics.h"

namespace wf {
namespace {

using nlohmann::json;

class Scanner {
public:
    bool too_deep = false;
    std::vector<FileReference> references;

    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(json::number_integer_t) { return value(); }
    bool number_unsigned(json::number_unsigned_t) { return value(); }
    bool number_float(json::number_float_t, const json::string_t&) { return value(); }
    bool binary(json::binary_t&) { return value(); }
    bool string(json::string_t& text) {
        // A string under "uri" in an element of the top-level "buffers" or "images".
        if (open_.size() == 3 && open_[1].is_array && !open_[2].is_array && key_ == "uri") {
            const std::string& array = open_[1].slot;
            if (array == "buffers" || array == "images")
                references.push_back({array == "buffers" ? "buffer" : "image", std::stoul(open_[2].slot), text});
            return true;
        }
        return value();
    }
    bool key(json::string_t& name) {
        key_ = name;
        return true;
    }
    bool start_object(size_t) { return open(false); }
    bool start_array(size_t) { return open(true); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool parse_error(size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

private:
    struct Container {
        std::string slot; // its key in its parent, or its index there
        bool is_array;
        size_t next_index = 0;
    };

    // A value other than a container: only its place in an array counts.
    bool value() {
        if (!open_.empty() && open_.back().is_array) ++open_.back().next_index;
        return true;
    }

    bool open(bool is_array) {
        if (open_.size() == kMaxJsonDepth) {
            too_deep = true;
            return false;
        }
        std::string slot;
        if (!open_.empty()) slot = open_.back().is_array ? std::to_string(open_.back().next_index++) : key_;
        open_.push_back({std::move(slot), is_array});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    std::vector<Container> open_; // from the outermost
    std::string key_;             // the last key read in the innermost object
};

} // namespace

std::vector<FileReference> scan_json(const std::string& path, std::string_view text) {
    Scanner scanner;
    json::sax_parse(text.begin(), text.end(), &scanner);
    if (scanner.too_deep) fail(path, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return std::move(scanner.references);
}

} // namespace wf
