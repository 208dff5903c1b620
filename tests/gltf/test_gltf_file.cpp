// test_gltf_file.cpp — the file around the glTF, as a hostile one may shape
// it: GLB framing, JSON nesting, and URIs that point outside the scene's
// folder. Each must fail with one line naming the file and the fault.
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
class GltfGlbFile : public GltfLoaderTest {
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

TEST_F(GltfGlbFile, WrongMagicIsNamedNotParsedAsJson) {
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

TEST_F(GltfGlbFile, VersionOtherThanTwoIsNamed) {
    set_word(glb_, 4, 1);
    expect_mentions(load_error(write("v1.glb")), {"v1.glb: GLB version 1 is not supported (expected 2)"});
}

TEST_F(GltfGlbFile, TruncatedChunksAreNamed) {
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

// `levels` arrays nested in the document's extras.
std::string nested_extras(GltfDocument doc, size_t levels, const fs::path& path) {
    doc.gltf["extras"] = "NEST";
    doc.write(path);
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("\"NEST\""), 6, std::string(levels, '[') + std::string(levels, ']'));
    std::ofstream(path) << text;
    return path.string();
}

// tinygltf copies extras into its Value by recursion: 100 000 levels
// overflowed the call stack (issue 15).
TEST_F(GltfLoaderTest, JsonNestedTooDeepIsNamed) {
    expect_mentions(load_error(nested_extras(one_triangle(), 100000, dir_ / "deep.gltf")),
                    {"deep.gltf: JSON nested deeper than 512 levels"});
    // The document and its extras object take one level each.
    EXPECT_EQ(load_gltf(nested_extras(one_triangle(), 511, dir_ / "fits.gltf")).triangle_count(), 1u);
    expect_mentions(load_error(nested_extras(one_triangle(), 512, dir_ / "over.gltf")), {"over.gltf: JSON nested"});
}

TEST_F(GltfLoaderTest, JsonNestedTooDeepInAGlbIsNamed) {
    GltfDocument doc = one_triangle();
    std::vector<unsigned char> glb = doc.glb();
    // The JSON chunk's last byte is padding or its closing brace; either way
    // an array of arrays fits before it as a new member.
    const std::string deep = ",\"extras\":" + std::string(1000, '[') + std::string(1000, ']');
    const size_t json_end = 20 + word_at(glb, 12);
    size_t brace = json_end - 1;
    while (glb[brace] != '}') --brace;
    glb.insert(glb.begin() + long(brace), deep.begin(), deep.end());
    const size_t padded = (deep.size() + 3) / 4 * 4;
    glb.insert(glb.begin() + long(json_end + deep.size()), padded - deep.size(), ' ');
    set_word(glb, 12, uint32_t(word_at(glb, 12) + padded));
    set_word(glb, 8, uint32_t(glb.size()));
    expect_mentions(load_error(write_text("deep.glb", as_text(glb))), {"deep.glb: JSON nested deeper than 512 levels"});
}

// tinygltf joins any URI to the scene's folder, so these were reported as
// missing files; none is looked for.
TEST_F(GltfLoaderTest, AbsoluteUrisAreRefused) {
    for (const std::string uri : {"/etc/passwd", "file:///etc/passwd", "C:\\x.bin", "%2Fetc%2Fpasswd", "\\\\host\\x"}) {
        GltfDocument doc;
        doc.gltf["buffers"] = {{{"uri", uri}, {"byteLength", 4}}};
        expect_mentions(load_error(doc.write(dir_ / "buffer.gltf")),
                        {"buffer.gltf: buffer 0: absolute URI '" + uri + "' lies outside the scene's folder"});
    }
    GltfDocument doc = one_triangle();
    doc.gltf["images"] = {{{"uri", "file:///etc/passwd"}}};
    expect_mentions(load_error(doc.write(dir_ / "image.gltf")),
                    {"image.gltf: image 0: absolute URI 'file:///etc/passwd' lies outside the scene's folder"});
}

// tinygltf goes on without an image it could not read; one outside the
// folder is refused all the same, used or not.
TEST_F(GltfLoaderTest, ImageOutsideTheFolderIsRefused) {
    fs::create_directories(dir_ / "scene");
    write_text("outside.png", "not read");
    GltfDocument doc = one_triangle();
    doc.gltf["images"] = {{{"uri", "../outside.png"}}};
    expect_mentions(load_error(doc.write(dir_ / "scene" / "escape.gltf")),
                    {"escape.gltf: refers to ", "outside.png, which lies outside the scene's folder"});
}

} // namespace
} // namespace wf
