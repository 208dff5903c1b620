// gltf_diagnostics.h — how the glTF loader speaks: one-line errors that
// name the file and the thing at fault, labels for the things it names, and
// the warnings, each said once, for what a file uses that the renderer does
// not (extensions, skins, morph targets, animations). Shared by every file of
// host/gltf/.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace wf {

// Throws InputError("where: what").
[[noreturn]] void fail(const std::string& where, const std::string& what);

// "mesh 'floor'", or "mesh 3" where the file leaves it unnamed.
std::string label(const char* kind, size_t index, const std::string& name);

// "node 3 'lamp'", or "node 3": the index always, the name where there is one.
std::string indexed_label(const char* kind, size_t index, const std::string& name);

// tinygltf's messages span lines and may quote a whole data URI; ours are one
// short line.
std::string one_line(const std::string& text);

// Refuses a file that requires an extension the renderer lacks; warns once of
// those it uses and the renderer ignores.
void check_extensions(const tinygltf::Model& model, const std::string& path, std::vector<std::string>& warnings);

// Core glTF features that are read past, each said once: the scene renders
// in its bind pose with no morph weights applied.
void check_core_features(const tinygltf::Model& model, std::vector<std::string>& warnings);

} // namespace wf
