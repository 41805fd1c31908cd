// GLB writer with textures: a textured material's image is embedded in the BIN chunk (its bytes
// exactly the PNG's) behind images (image/png), one repeating sampler and textures; the material
// names it as baseColorTexture; every primitive has TEXCOORD_0 with one UV per position (glTF's
// v = 1 - v); what textures add leaves the plain part of the file as it was. Inconsistent
// textures or UVs are refused.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <iterator>

#include "base/input_error.hpp"
#include "cube_mesh.hpp"
#include "glb_file.hpp"
#include "json_value.hpp"
#include "mesh/glb_writer.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

std::vector<std::uint8_t> bricks() {
    std::ifstream in(test::sourcePath("tests/data/bricks.png"), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A red box (untextured) and a textured box, each with its own vertices, and UVs u = x, v = y.
Mesh texturedBoxes() {
    Mesh m;
    m.materials = {{"red", {1, 0, 0}}, {"bricks", {1, 1, 1}, 0}};
    m.textures = {{"bricks.png", bricks()}};
    for (int b = 0; b < 2; ++b) {
        const Mesh box = test::boxMesh({float(3 * b), 0, 0}, {float(3 * b) + 1, 2, 1});
        const auto base = std::uint32_t(m.vertices.size());
        for (const auto& v : box.vertices) {
            m.vertices.push_back(v);
            m.uvs.push_back(b ? glm::vec2(v.x, v.y) : glm::vec2(0.0f));
        }
        for (const auto& t : box.triangles) {
            m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
            m.triangleMaterials.push_back(std::uint32_t(b));
        }
    }
    return m;
}

TEST(GlbTexture, TheImageIsEmbeddedAndNamedByTheMaterialWithARepeatingSampler) {
    test::TempDir dir;
    const Mesh mesh = texturedBoxes();
    writeGlb(mesh, dir.file("t.glb"));
    const test::Glb glb = test::parseGlb(test::readFile(dir.file("t.glb")));
    const test::Json json = test::parseJson(glb.json);
    ASSERT_EQ(json["images"].size(), 1u);
    const test::Json& image = json["images"][0];
    EXPECT_EQ(image["mimeType"].string, "image/png");
    EXPECT_EQ(image["name"].string, "bricks.png");
    const test::Json& view = json["bufferViews"][std::size_t(image["bufferView"].number)];
    EXPECT_FALSE(view.has("target")) << "an image's view is no vertex or index buffer";
    const auto offset = std::size_t(view["byteOffset"].number), length = std::size_t(view["byteLength"].number);
    ASSERT_LE(offset + length, glb.bin.size());
    const std::vector<std::uint8_t> embedded(glb.bin.begin() + std::ptrdiff_t(offset), glb.bin.begin() + std::ptrdiff_t(offset + length));
    EXPECT_EQ(embedded, bricks()) << "the PNG's bytes, exactly";
    ASSERT_EQ(json["samplers"].size(), 1u);
    EXPECT_EQ(json["samplers"][0]["wrapS"].number, 10497.0) << "REPEAT";
    EXPECT_EQ(json["samplers"][0]["wrapT"].number, 10497.0);
    ASSERT_EQ(json["textures"].size(), 1u);
    EXPECT_EQ(json["textures"][0]["sampler"].number, 0.0);
    EXPECT_EQ(json["textures"][0]["source"].number, 0.0);
    EXPECT_FALSE(json["materials"][0]["pbrMetallicRoughness"].has("baseColorTexture")) << "red has none";
    const test::Json& pbr = json["materials"][1]["pbrMetallicRoughness"];
    EXPECT_EQ(pbr["baseColorTexture"]["index"].number, 0.0);
    for (std::size_t a = 0; a < 4; ++a) EXPECT_EQ(pbr["baseColorFactor"][a].number, 1.0) << "white: the image as it is";
    EXPECT_EQ(json["buffers"][0]["byteLength"].number, double(glb.bin.size()));
}

TEST(GlbTexture, EveryPrimitiveHasTexcoordsOnePerPositionWithVFlipped) {
    test::TempDir dir;
    const Mesh mesh = texturedBoxes();
    writeGlb(mesh, dir.file("t.glb"));
    const test::Glb glb = test::parseGlb(test::readFile(dir.file("t.glb")));
    const test::Json json = test::parseJson(glb.json);
    const test::Json& primitives = json["meshes"][0]["primitives"];
    ASSERT_EQ(primitives.size(), 2u);
    const auto uv = std::size_t(primitives[0]["attributes"]["TEXCOORD_0"].number);
    EXPECT_EQ(primitives[1]["attributes"]["TEXCOORD_0"].number, double(uv));
    const test::Json& accessor = json["accessors"][uv];
    EXPECT_EQ(accessor["count"].number, json["accessors"][0]["count"].number) << "TEXCOORD_0 count = POSITION count";
    EXPECT_EQ(accessor["type"].string, "VEC2");
    EXPECT_EQ(accessor["componentType"].number, 5126.0);
    const test::Json& view = json["bufferViews"][std::size_t(accessor["bufferView"].number)];
    EXPECT_EQ(view["target"].number, 34962.0);
    EXPECT_EQ(view["byteLength"].number, double(mesh.vertices.size() * 8));
    const auto start = std::size_t(view["byteOffset"].number);
    EXPECT_EQ(start % 4, 0u);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        EXPECT_EQ(std::bit_cast<float>(test::u32(glb.bin, start + 8 * v)), mesh.uvs[v].x);
        EXPECT_EQ(std::bit_cast<float>(test::u32(glb.bin, start + 8 * v + 4)), 1.0f - mesh.uvs[v].y) << "glTF's v runs down";
    }
}

TEST(GlbTexture, WithoutTexturesNothingIsAdded) {
    test::TempDir dir;
    Mesh mesh = texturedBoxes();
    mesh.materials[1].texture = -1;
    mesh.textures.clear();
    mesh.uvs.clear();
    writeGlb(mesh, dir.file("plain.glb"));
    const test::Json json = test::parseJson(test::parseGlb(test::readFile(dir.file("plain.glb"))).json);
    EXPECT_FALSE(json.has("images"));
    EXPECT_FALSE(json.has("samplers"));
    EXPECT_FALSE(json.has("textures"));
    EXPECT_FALSE(json["meshes"][0]["primitives"][0]["attributes"].has("TEXCOORD_0"));
    EXPECT_EQ(json["bufferViews"].size(), 2u);
}

TEST(GlbTexture, InconsistentTexturesOrUvsAreRefusedAndLeaveNoFile) {
    test::TempDir dir;
    const auto refused = [&](const Mesh& m, const std::string& fragment) {
        try {
            writeGlb(m, dir.file("bad.glb"));
            ADD_FAILURE() << "expected InputError: " << fragment;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
        EXPECT_FALSE(std::filesystem::exists(dir.file("bad.glb")));
    };
    Mesh m = texturedBoxes();
    m.uvs.pop_back();
    refused(m, "15 UV coordinates for 16 vertices");
    m = texturedBoxes();
    m.uvs[3].x = NAN;
    refused(m, "vertex 3: UV coordinate is not a finite number");
    m = texturedBoxes();
    m.materials[1].texture = 1;
    refused(m, "material 1: texture 1 out of range");
    m = texturedBoxes();
    m.textures[0].name = "bricks.jpg";
    refused(m, "texture 0: file name 'bricks.jpg'");
    m = texturedBoxes();
    m.textures[0].png = {1, 2, 3};
    refused(m, "texture 0: image 'bricks.png' is not a PNG");
    m = texturedBoxes();
    m.materials[1].texture = -1;
    refused(m, "UV coordinates but no textured material");
}

}  // namespace
}  // namespace shapevo
