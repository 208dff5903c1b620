// gltf_file.h — a glTF file read and parsed by tinygltf, in the scene's
// folder sandbox: external buffers and images must lie in the scene's folder
// or below it, so a file from anywhere cannot make the renderer read files
// elsewhere ("../../etc/passwd" as a buffer URI; an absolute URI, "/etc/passwd"
// or "file:///etc/passwd", is refused outright). Images stay encoded
// (gltf_textures.h decodes those materials use).
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace wf {

// The file's bytes. Throws InputError naming `path` when it is missing, not a
// regular file, unreadable, empty or larger than tinygltf takes (4 GiB).
std::vector<unsigned char> read_gltf_file(const std::string& path);

// The model in `bytes`, GLB or JSON by its magic; `path` names the file in
// messages and its folder is the sandbox. Throws InputError naming `path`.
tinygltf::Model parse_model(const std::string& path, const std::vector<unsigned char>& bytes);

// A URI's %XX escapes decoded, as tinygltf decodes them before looking for the file.
std::string uri_decode(const std::string& uri);

} // namespace wf
