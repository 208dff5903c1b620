// gltf_glb.h — the GLB container (glTF 2.0, "Binary glTF Layout") checked
// before tinygltf reads it, because tinygltf takes the header's word: it does
// not check the version, and lets a BIN chunk end up to 8 bytes past the file
// (its length is compared with the GLB's without the chunk's own header). And
// a file that is neither GLB nor JSON is named as a GLB with the wrong magic,
// not reported as broken JSON.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace wf {

// Whether `bytes` are GLB: they start with the magic "glTF". A file that is
// not JSON text either is refused, as a GLB whose magic is wrong, where its
// name ends in .glb or its first bytes are not text. Throws InputError naming `path`.
bool is_glb(const std::string& path, const std::vector<unsigned char>& bytes);

// A GLB's JSON chunk, once the header (version 2, a length the file holds)
// and every chunk within that length are checked. Throws InputError naming `path`.
std::string_view glb_json_chunk(const std::string& path, const std::vector<unsigned char>& bytes);

} // namespace wf
