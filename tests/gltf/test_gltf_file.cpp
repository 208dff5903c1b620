// test_gltf_file.cpp — the file around the glTF, as a hostile one may shape
// it: GLB framing. Each must fail with one line naming the file and the fault.
#include "gltf/gltf_document.h"

#include <cstring>

namespace wf {
namespace {

GltfDocument one_triangle() {
    GltfDocument doc;
    doc.add_mesh_node("triangle", triangle_primitive(doc.add_vec3(kTriangle)));
    return doc;
}

std::string as_text(const std::vector<unsigned char>& bytes) { return std::string(bytes.begin(), bytes.end()); }

uint32_t word_at(const std::vector<unsigned char>& bytes, size_t offset) {
    uint32_t word;
    std::memcpy(&word, bytes.data() + offset, sizeof word);
    return word;
}

void set_word(std::vector<unsigned char>& bytes, size_t offset, uint32_t word) {
    std::memcpy(bytes.data() + offset, &word, sizeof word);
}

// The GLB of one_triangle(), checked to load, so that each test below fails
// for the fault it makes and nothing else.
class GlbFile : public GltfLoaderTest {
protected:
    void SetUp() override {
        GltfLoaderTest::SetUp();
        glb_ = one_triangle().glb();
        bin_chunk_ = 20 + word_at(glb_, 12);
        ASSERT_EQ(load_gltf(write("whole.glb")).triangle_count(), 1u);
    }

    std::string write(const std::string& name) const { return write_text(name, as_text(glb_)); }

    std::vector<unsigned char> glb_;
    size_t bin_chunk_ = 0; // where the BIN chunk's header starts
};

TEST_F(GlbFile, WrongMagicIsNamedNotParsedAsJson) {
    std::memcpy(glb_.data(), "PK\3\4", 4);
    expect_mentions(load_error(write("zip.glb")),
                    {"zip.glb: not a GLB file (magic is 0x04034B50, expected 0x46546C67 'glTF')"});
    // Whatever the name, bytes that are not text cannot be JSON.
    expect_mentions(load_error(write_text("png.gltf", "\x89PNG\r\n\x1a\n")), {"png.gltf: not a GLB file", "0x474E5089"});
    // Nor does the name decide for JSON text.
    const std::string json_path = one_triangle().write(dir_ / "text.gltf");
    fs::copy_file(json_path, dir_ / "text.glb");
    EXPECT_EQ(load_gltf((dir_ / "text.glb").string()).triangle_count(), 1u);
}

TEST_F(GlbFile, VersionOtherThanTwoIsNamed) {
    set_word(glb_, 4, 1);
    expect_mentions(load_error(write("v1.glb")), {"v1.glb: GLB version 1 is not supported (expected 2)"});
}

TEST_F(GlbFile, TruncatedChunksAreNamed) {
    const size_t size = glb_.size();
    glb_.resize(size - 4);
    expect_mentions(load_error(write("cut.glb")),
                    {"cut.glb: truncated GLB: its header gives a length of " + std::to_string(size) +
                     " bytes, the file has " + std::to_string(size - 4)});
    glb_.resize(size);

    const uint32_t json_length = word_at(glb_, 12);
    set_word(glb_, 12, uint32_t(size));
    expect_mentions(load_error(write("json.glb")),
                    {"json.glb: truncated GLB: chunk 0 at byte 12 (JSON) claims " + std::to_string(size) + " bytes, " +
                     std::to_string(size - 20) + " remain"});
    set_word(glb_, 12, json_length);

    // tinygltf's own check let a BIN chunk end 8 bytes past the file, and
    // copied those 8 bytes into the buffer.
    const uint32_t bin_length = word_at(glb_, bin_chunk_);
    set_word(glb_, bin_chunk_, bin_length + 8);
    expect_mentions(load_error(write("bin.glb")),
                    {"bin.glb: truncated GLB: chunk 1 at byte " + std::to_string(bin_chunk_) + " (BIN) claims " +
                     std::to_string(bin_length + 8) + " bytes, " + std::to_string(bin_length) + " remain"});
    set_word(glb_, bin_chunk_, bin_length);

    glb_.resize(bin_chunk_ + 4);
    set_word(glb_, 8, uint32_t(glb_.size()));
    expect_mentions(load_error(write("header.glb")),
                    {"header.glb: truncated GLB: chunk 1 at byte " + std::to_string(bin_chunk_) +
                     " has 4 of its 8 header bytes"});
}

} // namespace
} // namespace wf
