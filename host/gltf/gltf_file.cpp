// gltf_file.cpp — see gltf_file.h.
#include "gltf/gltf_file.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string_view>

#include "base/input_file.h"
#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_glb.h"
#include "gltf/gltf_json_scan.h"
#include "gltf/gltf_textures.h"

namespace wf {
namespace {

// What tinygltf can take; checked on the file's size before reading it, and
// on bytes handed in directly.
void check_size(const std::string& path, uint64_t size) {
    if (size == 0) fail(path, "empty file");
    // tinygltf takes lengths as unsigned int.
    if (size > std::numeric_limits<unsigned int>::max()) fail(path, "file larger than 4 GiB");
}

// External buffers and images must lie in the scene's folder or below it: a
// file from anywhere must not make the renderer read files elsewhere
// ("../../etc/passwd" as a buffer URI).
// Nor may it make the renderer wait: a URI naming a FIFO or a device inside
// the folder is refused before it is opened (base/input_file.h).
struct SceneFolder {
    std::filesystem::path root;
    std::string refused; // the first file refused, for the message (tinygltf's own is cut to length)
    std::string why;     // why it was
};

// tinygltf's own opens the file to see whether it exists, and opening a FIFO
// waits for a writer.
bool file_exists(const std::string& file, void*) {
    std::error_code ec;
    return std::filesystem::exists(file, ec);
}

bool read_inside_folder(std::vector<unsigned char>* out, std::string* error, const std::string& file, void* user) {
    SceneFolder& folder = *static_cast<SceneFolder*>(user);
    std::error_code ec;
    const std::filesystem::path relative = std::filesystem::weakly_canonical(file, ec).lexically_relative(folder.root);
    std::string why = ec || relative.empty() || *relative.begin() == ".." ? "which lies outside the scene's folder"
                                                                           : not_a_regular_file(file);
    if (!why.empty()) {
        if (folder.refused.empty()) folder.refused = file, folder.why = why;
        if (error) *error += why;
        return false;
    }
    return tinygltf::ReadWholeFile(out, error, file, nullptr);
}

// A URI with a scheme ("file:", "http:", "C:") or a root ("/etc/passwd",
// "\\\\server\\share") names a file wherever it likes; tinygltf would join it to
// the scene's folder anyway and report the result missing.
bool is_absolute(const std::string& uri) {
    if (!uri.empty() && (uri[0] == '/' || uri[0] == '\\')) return true;
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (size_t i = 1; i < colon; ++i) { // RFC 3986: a letter, then letters, digits, "+", "-" or "."
        const char c = uri[i];
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return true;
}

// Data URIs carry their bytes; every other URI must be a path below the
// scene's folder, as tinygltf decodes it.
void check_references(const std::string& path, const std::vector<FileReference>& references) {
    for (const FileReference& reference : references) {
        if (reference.uri.compare(0, 5, "data:") == 0 || !is_absolute(uri_decode(reference.uri))) continue;
        fail(path + ": " + reference.kind + " " + std::to_string(reference.index),
             "absolute URI '" + one_line(reference.uri) + "' lies outside the scene's folder");
    }
}

} // namespace

std::string uri_decode(const std::string& uri) {
    std::string decoded;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
            std::isxdigit((unsigned char)uri[i + 2])) {
            decoded += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return decoded;
}

std::vector<unsigned char> read_gltf_file(const std::string& path) {
    if (const std::string why = not_a_regular_file(path); !why.empty()) fail(path, why);
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in ? std::streamoff(in.tellg()) : -1;
    if (size < 0) fail(path, "cannot read file");
    check_size(path, uint64_t(size));
    std::vector<unsigned char> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) fail(path, "cannot read file");
    return bytes;
}

tinygltf::Model parse_model(const std::string& path, const std::vector<unsigned char>& bytes) {
    check_size(path, bytes.size());
    // The magic decides, not the extension: a .gltf may well hold GLB bytes.
    const bool binary = is_glb(path, bytes);
    const std::string_view json =
        binary ? glb_json_chunk(path, bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    check_references(path, scan_json(path, json));
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    const auto length = static_cast<unsigned int>(bytes.size());

    tinygltf::TinyGLTF parser;
    // Images are kept encoded; gltf_textures.cpp decodes those materials use,
    // so a missing or broken image is reported with the material.
    parser.SetImageLoader(keep_image_encoded, nullptr);
    std::error_code ec;
    SceneFolder folder{std::filesystem::weakly_canonical(std::filesystem::absolute(path).parent_path(), ec), {}, {}};
    parser.SetFsCallbacks({&file_exists, &tinygltf::ExpandFilePath, &read_inside_folder,
                           &tinygltf::WriteWholeFile, &folder});
    tinygltf::Model model;
    std::string error;
    std::string warning; // only about images, which gltf_textures.cpp reports itself
    bool parsed = false;
    try {
        parsed = binary ? parser.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                      length, base_dir)
                        : parser.LoadASCIIFromString(&model, &error, &warning,
                                                     reinterpret_cast<const char*>(bytes.data()),
                                                     length, base_dir);
    } catch (const std::exception& e) { // tinygltf's own checks can throw (std::vector::at)
        error = e.what();
    }
    // Whether or not tinygltf went on without it (it does for images).
    if (!folder.refused.empty()) fail(path, "refers to " + folder.refused + ", " + folder.why);
    if (!parsed) {
        const std::string detail = one_line(error);
        fail(path, std::string(binary ? "cannot load GLB" : "cannot load glTF") +
                       (detail.empty() ? "" : ": " + detail));
    }
    return model;
}

} // namespace wf
