// gltf_mutator.cpp — libFuzzer's custom mutator for fuzz_gltf_loader: where
// the input is a glTF (JSON text, or a GLB whose JSON chunk is), it edits the
// document as JSON, so that the loader's checks past tinygltf's parse are
// what gets fuzzed. Byte mutations of a real file almost always break its
// JSON; these keep it whole and aim at what a hostile file changes: numbers
// pushed to the edges of int and float range, index links broken (out of
// range, self links, cycles, second parents), accessor layouts
// (count, byteOffset, componentType, type), node chains thousands deep, URIs
// that leave the folder, keys deleted, elements duplicated, values moved to
// where another type is expected. Anything that is not such a glTF, and one
// call in four, goes to libFuzzer's own byte mutator. WF_FUZZ_MUTATOR=bytes
// leaves every call to it, for comparison.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

using nlohmann::json;
using Random = std::mt19937; // minstd_rand's first draw from a small seed is always small

// How many calls each mutator took, said at exit (scripts/fuzz.sh reports it).
struct Counts {
    size_t structure = 0;
    size_t bytes = 0;
    ~Counts() { std::fprintf(stderr, "mutator: %zu structure-aware, %zu byte mutations\n", structure, bytes); }
} counts;

size_t pick(Random& random, size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(random); }

template <typename T, size_t N>
const T& pick_from(Random& random, const T (&choices)[N]) {
    return choices[pick(random, N)];
}

// Deeper than any glTF needs; it keeps the mutator's own recursion (dump())
// short on inputs that byte mutations nested deep.
constexpr int kMaxDepth = 64;

// Number text that json cannot hold as it is (NaN, overflow to Inf, integers
// past 64 bits): written as a marked string, put in raw after dump().
const char kRawMark[] = "@wf-raw:";
const char* const kRawNumbers[] = {"1e999", "-1e999", "NaN", "Infinity", "-0", "1e-400",
                                   "18446744073709551616", "-9223372036854775809"};

// A glTF split for editing: the JSON text, and for a GLB what follows its
// JSON chunk (the BIN chunk and any other), kept as it is.
struct Document {
    bool glb = false;
    std::string text;
    std::vector<uint8_t> tail;
};

uint32_t word_at(const uint8_t* data, size_t offset) {
    uint32_t word;
    std::memcpy(&word, data + offset, sizeof word);
    return word;
}

bool split(const uint8_t* data, size_t size, Document& document) {
    if (size >= 20 && std::memcmp(data, "glTF", 4) == 0) {
        const uint32_t length = word_at(data, 12);
        if (std::memcmp(data + 16, "JSON", 4) != 0 || length > size - 20) return false;
        document.glb = true;
        document.text.assign(reinterpret_cast<const char*>(data + 20), length);
        document.tail.assign(data + 20 + length, data + size);
        return true;
    }
    document.text.assign(reinterpret_cast<const char*>(data), size);
    return true;
}

std::vector<uint8_t> join(const Document& document) {
    if (!document.glb) return {document.text.begin(), document.text.end()};
    std::string text = document.text;
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::vector<uint8_t> out;
    const auto word = [&out](size_t value) {
        for (int shift = 0; shift < 32; shift += 8) out.push_back(uint8_t(value >> shift));
    };
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    word(2);
    word(20 + text.size() + document.tail.size());
    word(text.size());
    out.insert(out.end(), {'J', 'S', 'O', 'N'});
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), document.tail.begin(), document.tail.end());
    return out;
}

// A value in the document and the key it sits under (for an array's
// element, the array's key).
struct Slot {
    json* value;
    std::string key;
};

std::vector<Slot> slots(json& root) {
    std::vector<Slot> found;
    std::vector<Slot> pending{{&root, ""}};
    while (!pending.empty()) {
        const Slot slot = pending.back();
        pending.pop_back();
        found.push_back(slot);
        if (slot.value->is_object())
            for (auto& [key, value] : slot.value->items()) pending.push_back({&value, key});
        else if (slot.value->is_array())
            for (json& element : *slot.value) pending.push_back({&element, slot.key});
    }
    return found;
}

// The top-level array an index under `key` points into, or null.
const char* indexed_array(const std::string& key) {
    static const std::pair<const char*, const char*> kLinks[] = {
        {"mesh", "meshes"},         {"camera", "cameras"},     {"skin", "skins"},
        {"material", "materials"},  {"indices", "accessors"},  {"POSITION", "accessors"},
        {"NORMAL", "accessors"},    {"TANGENT", "accessors"},  {"TEXCOORD_0", "accessors"},
        {"TEXCOORD_1", "accessors"}, {"COLOR_0", "accessors"}, {"input", "accessors"},
        {"output", "accessors"},    {"bufferView", "bufferViews"}, {"buffer", "buffers"},
        {"source", "images"},       {"sampler", "samplers"},   {"index", "textures"},
        {"children", "nodes"},      {"nodes", "nodes"},        {"node", "nodes"},
        {"scene", "scenes"},        {"joints", "nodes"}};
    for (const auto& [name, array] : kLinks)
        if (key == name) return array;
    return nullptr;
}

json edge_number(Random& random, const json& old) {
    const double value = old.is_number() ? old.get<double>() : 1.0;
    switch (pick(random, 12)) {
    case 0: return 0;
    case 1: return -1;
    case 2: return value + 1;
    case 3: return value - 1;
    case 4: return -value;
    case 5: return value * 2;
    case 6: return value * 1e30;
    case 7: return pick_from(random, {1e39, 3.4e38, 1.7e308, 2147483647.0, 4294967295.0, 4294967296.0, 9007199254740993.0});
    case 8: return pick_from(random, {1e-45, 1e-320, 1e-38, -0.0});
    case 9: return std::string(kRawMark) + pick_from(random, kRawNumbers);
    case 10: return pick_from(random, {5120, 5121, 5122, 5123, 5124, 5125, 5126, 0});
    default: return pick(random, 2) ? json(nullptr) : json(std::string("1"));
    }
}

json broken_link(Random& random, const json& root, const std::string& key, const json& old) {
    const json* target = root.contains(indexed_array(key)) ? &root[indexed_array(key)] : nullptr;
    const size_t n = target && target->is_array() ? target->size() : 0;
    switch (pick(random, 6)) {
    case 0: return -1;
    case 1: return n;
    case 2: return n + 1;
    case 3: return 2147483647;
    case 4: return old.is_number_integer() ? old.get<int64_t>() + 1 : 0;
    default: return pick(random, n);
    }
}

// Node links a tree must not have, or a chain deeper than a call stack.
void break_hierarchy(Random& random, json& root) {
    if (!root.contains("nodes") || !root["nodes"].is_array() || root["nodes"].empty()) return;
    json& nodes = root["nodes"];
    const size_t i = pick(random, nodes.size()), j = pick(random, nodes.size());
    const auto add_child = [&nodes](size_t parent, size_t child) {
        if (!nodes[parent].is_object()) return;
        json& children = nodes[parent]["children"];
        if (!children.is_array()) children = json::array();
        children.push_back(child);
    };
    switch (pick(random, 4)) {
    case 0: add_child(i, i); break;
    case 1: add_child(i, j), add_child(j, i); break;
    case 2: add_child(i, j); break; // a second parent, unless j was a root
    default: { // node i gets a chain of new nodes below it, deeper than a recursive walk would survive
        const size_t length = 1 + pick(random, 20000);
        for (size_t k = 0; k < length; ++k)
            nodes.push_back(k + 1 < length ? json{{"children", {nodes.size() + 1}}} : json::object());
        add_child(i, nodes.size() - length);
    }
    }
}

void mutate_once(Random& random, json& root) {
    const std::vector<Slot> all = slots(root);
    const Slot& slot = all[pick(random, all.size())];
    json& value = *slot.value;
    switch (pick(random, 8)) {
    case 0:
    case 1: { // a number, pushed to an edge
        std::vector<json*> numbers;
        for (const Slot& s : all)
            if (s.value->is_number()) numbers.push_back(s.value);
        if (!numbers.empty()) {
            json& number = *numbers[pick(random, numbers.size())];
            number = edge_number(random, number);
        }
        break;
    }
    case 2: { // an index link, broken
        std::vector<const Slot*> links;
        for (const Slot& s : all)
            if (s.value->is_number_integer() && indexed_array(s.key)) links.push_back(&s);
        if (!links.empty()) {
            const Slot& link = *links[pick(random, links.size())];
            *link.value = broken_link(random, root, link.key, *link.value);
        }
        break;
    }
    case 3: break_hierarchy(random, root); break;
    case 4: // a key deleted
        if (value.is_object() && !value.empty()) {
            auto it = value.begin();
            std::advance(it, std::ptrdiff_t(pick(random, value.size())));
            value.erase(it);
        }
        break;
    case 5: // an element duplicated
        if (value.is_array() && !value.empty()) value.push_back(json(value[pick(random, value.size())]));
        break;
    case 6: // a value of another type put in its place
        value = json(*all[pick(random, all.size())].value);
        break;
    default: // a string the loader must handle
        if (slot.key == "uri")
            value = pick_from<const char*>(random, {"../outside.bin", "/etc/passwd", "file:///etc/passwd", "C:\\x", "%2e%2e/x",
                                       "", "data:application/octet-stream;base64,AAAA"});
        else if (slot.key == "type")
            value = pick_from<const char*>(random, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT4", "VEC5", "point", "spot"});
        else if (value.is_string())
            value = pick_from<const char*>(random, {"", "OPAQUE", "MASK", "BLEND", "perspective", "KHR_materials_volume"});
    }
}

// The document with raw number text put where kRawMark strings stand.
std::string dump_with_raw_numbers(const json& root) {
    std::string text = root.dump();
    const std::string mark = std::string("\"") + kRawMark;
    for (size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at)) {
        const size_t end = text.find('"', at + mark.size());
        if (end == std::string::npos) break;
        text.replace(at, end + 1 - at, text.substr(at + mark.size(), end - at - mark.size()));
    }
    return text;
}

bool structure_mutation(uint8_t* data, size_t& size, size_t max_size, Random& random) {
    Document document;
    if (!split(data, size, document)) return false;
    bool too_deep = false;
    json root = json::parse(
        document.text,
        [&too_deep](int depth, json::parse_event_t, json&) {
            too_deep = too_deep || depth > kMaxDepth;
            return !too_deep;
        },
        false);
    if (too_deep || !root.is_object()) return false;
    for (size_t n = 1 + pick(random, 3); n > 0; --n) mutate_once(random, root);
    document.text = dump_with_raw_numbers(root);
    const std::vector<uint8_t> out = join(document);
    if (out.size() > max_size) return false;
    std::memcpy(data, out.data(), out.size());
    size = out.size();
    return true;
}

} // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
    static const bool bytes_only = [] {
        const char* mutator = std::getenv("WF_FUZZ_MUTATOR");
        return mutator && std::string(mutator) == "bytes";
    }();
    Random random(seed);
    if (!bytes_only && pick(random, 4) != 0 && structure_mutation(data, size, max_size, random)) {
        ++counts.structure;
        return size;
    }
    ++counts.bytes;
    return LLVMFuzzerMutate(data, size, max_size);
}
