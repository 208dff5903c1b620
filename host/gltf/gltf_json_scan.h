// gltf_json_scan.h — a glTF's JSON read once, lightly, before tinygltf parses
// it, for what tinygltf cannot be trusted with:
// - nesting: tinygltf turns `extras` and `extensions` into its own Value by
//   recursion, so some hundred thousand nested arrays overflow the call
//   stack; deeper than kMaxJsonDepth is an InputError;
// - the URIs of buffers and images, for the folder sandbox (gltf_file.h),
//   since tinygltf only hands over the path it made of one.
// JSON that does not parse is left for tinygltf to report.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace wf {

// No glTF needs more than a handful of levels; extras may nest what their
// application likes, within reason.
constexpr size_t kMaxJsonDepth = 512;

// A buffer's or an image's URI, as the file writes it.
struct FileReference {
    const char* kind; // "buffer" or "image"
    size_t index;
    std::string uri;
};

// The buffer and image URIs of `json`. Throws InputError naming `path` when
// it nests deeper than kMaxJsonDepth.
std::vector<FileReference> scan_json(const std::string& path, std::string_view json);

} // namespace wf
