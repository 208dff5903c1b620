// gltf_glb.cpp — see gltf_glb.h. GLB words are little-endian, as is every
// host this runs on.
#include "gltf/gltf_glb.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "gltf/gltf_diagnostics.h"

namespace wf {
namespace {

// glTF 2.0, "Binary glTF Layout": a 12-byte header (magic, version, length)
// then chunks, each an 8-byte header (length, type) and its data.
constexpr uint32_t kMagic = 0x46546C67; // "glTF"
constexpr size_t kHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;
constexpr uint32_t kVersion = 2;
constexpr uint32_t kJsonChunk = 0x4E4F534A; // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;  // "BIN\0"

uint32_t word_at(const std::vector<unsigned char>& bytes, size_t offset) {
    uint32_t word;
    std::memcpy(&word, bytes.data() + offset, sizeof word);
    return word;
}

std::string hex(uint32_t word) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", word);
    return text;
}

std::string chunk_type(uint32_t type) {
    return type == kJsonChunk ? "JSON" : type == kBinChunk ? "BIN" : hex(type);
}

bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// A UTF-8 byte order mark, which JSON text may start with.
size_t bom_length(const std::vector<unsigned char>& bytes) {
    return bytes.size() >= 3 && std::memcmp(bytes.data(), "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
}

// JSON text that is a glTF starts with an object.
bool starts_as_json(const std::vector<unsigned char>& bytes) {
    size_t i = bom_length(bytes);
    while (i < bytes.size() && is_space(bytes[i])) ++i;
    return i < bytes.size() && bytes[i] == '{';
}

// Text, however broken, is left for the JSON parser to name what is wrong.
bool starts_as_text(const std::vector<unsigned char>& bytes) {
    if (bom_length(bytes) > 0) return true;
    for (size_t i = 0; i < bytes.size() && i < 4; ++i)
        if (!(bytes[i] >= 0x20 && bytes[i] < 0x7F) && !is_space(bytes[i])) return false;
    return true;
}

} // namespace

bool is_glb(const std::string& path, const std::vector<unsigned char>& bytes) {
    if (bytes.size() >= 4 && word_at(bytes, 0) == kMagic) return true;
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (starts_as_json(bytes) || (extension != ".glb" && starts_as_text(bytes))) return false;
    if (bytes.size() < 4) fail(path, "not a GLB file (" + std::to_string(bytes.size()) + " bytes, too short for its magic)");
    fail(path, "not a GLB file (magic is " + hex(word_at(bytes, 0)) + ", expected " + hex(kMagic) + " 'glTF')");
}

std::string_view glb_json_chunk(const std::string& path, const std::vector<unsigned char>& bytes) {
    if (bytes.size() < kHeaderBytes)
        fail(path, "truncated GLB: " + std::to_string(bytes.size()) + " bytes, less than the " +
                       std::to_string(kHeaderBytes) + "-byte header");
    const uint32_t version = word_at(bytes, 4);
    if (version != kVersion)
        fail(path, "GLB version " + std::to_string(version) + " is not supported (expected " +
                       std::to_string(kVersion) + ")");
    const uint32_t length = word_at(bytes, 8);
    if (length > bytes.size())
        fail(path, "truncated GLB: its header gives a length of " + std::to_string(length) + " bytes, the file has " +
                       std::to_string(bytes.size()));
    std::string_view json;
    size_t offset = kHeaderBytes;
    for (size_t chunk = 0; offset < length; ++chunk) {
        const std::string at = "chunk " + std::to_string(chunk) + " at byte " + std::to_string(offset);
        if (length - offset < kChunkHeaderBytes)
            fail(path, "truncated GLB: " + at + " has " + std::to_string(length - offset) + " of its " +
                           std::to_string(kChunkHeaderBytes) + " header bytes");
        const uint32_t data_length = word_at(bytes, offset);
        const uint32_t type = word_at(bytes, offset + 4);
        const size_t data = offset + kChunkHeaderBytes;
        if (data_length > length - data)
            fail(path, "truncated GLB: " + at + " (" + chunk_type(type) + ") claims " + std::to_string(data_length) +
                           " bytes, " + std::to_string(length - data) + " remain");
        if (chunk == 0) {
            if (type != kJsonChunk) fail(path, "GLB " + at + " is " + chunk_type(type) + ", expected JSON");
            if (data_length == 0) fail(path, "GLB JSON chunk is empty");
            json = std::string_view(reinterpret_cast<const char*>(bytes.data() + data), data_length);
        }
        offset = data + data_length;
    }
    if (json.empty()) fail(path, "GLB has no JSON chunk");
    return json;
}

} // namespace wf
