// GLB writer: the file parses back as binary glTF 2.0 (header, aligned JSON and BIN chunks) and
// its buffer holds exactly the mesh's positions and indices, with the counts and bounds in JSON.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "cube_mesh.hpp"
#include "mesh/glb_writer.hpp"
#include "base/input_error.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

std::uint32_t u32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(std::uint8_t(bytes.at(at + std::size_t(i)))) << (8 * i);
    return v;
}

struct Glb {
    std::string json, bin;
    bool hasBin = false;
};

/// Parses the GLB container, checking header and chunk framing as it goes.
Glb parseGlb(const std::string& bytes) {
    Glb g;
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(u32(bytes, 0), 0x46546C67u) << "magic 'glTF'";
    EXPECT_EQ(u32(bytes, 4), 2u) << "version";
    EXPECT_EQ(u32(bytes, 8), bytes.size()) << "total length";
    const std::uint32_t jsonLength = u32(bytes, 12);
    EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au) << "first chunk is JSON";
    EXPECT_EQ(jsonLength % 4, 0u) << "JSON chunk aligned";
    g.json = bytes.substr(20, jsonLength);
    std::size_t at = 20 + std::size_t(jsonLength);
    if (at < bytes.size()) {
        const std::uint32_t binLength = u32(bytes, at);
        EXPECT_EQ(u32(bytes, at + 4), 0x004E4942u) << "second chunk is BIN";
        EXPECT_EQ(binLength % 4, 0u) << "BIN chunk aligned";
        g.bin = bytes.substr(at + 8, binLength);
        g.hasBin = true;
        at += 8 + std::size_t(binLength);
    }
    EXPECT_EQ(at, bytes.size()) << "nothing after the chunks";
    return g;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// JSON braces and brackets balance outside strings (a cheap well-formedness check).
bool balanced(const std::string& json) {
    int depth = 0;
    bool inString = false;
    for (char c : json) {
        if (c == '"') inString = !inString;
        if (inString) continue;
        if (c == '{' || c == '[') ++depth;
        if (c == '}' || c == ']') --depth;
        if (depth < 0) return false;
    }
    return depth == 0 && !inString;
}

TEST(GlbWriter, BoxParsesBackWithItsPositionsIndicesCountsAndBounds) {
    test::TempDir dir;
    const Mesh mesh = test::boxMesh({-1.0f, 0.5f, -2.0f}, {3.0f, 1.25f, 4.0f});
    const std::string path = dir.file("model.glb");
    writeGlb(mesh, path);
    const Glb g = parseGlb(test::readFile(path));
    ASSERT_TRUE(g.hasBin);
    EXPECT_TRUE(balanced(g.json)) << g.json;
    EXPECT_TRUE(contains(g.json, R"("version":"2.0")"));
    EXPECT_TRUE(contains(g.json, R"("POSITION":0)"));
    EXPECT_TRUE(contains(g.json, R"("count":8,"type":"VEC3")")) << g.json;
    EXPECT_TRUE(contains(g.json, R"("count":36,"type":"SCALAR")")) << g.json;
    EXPECT_TRUE(contains(g.json, R"("min":[-1,0.5,-2],"max":[3,1.25,4])")) << g.json;
    EXPECT_TRUE(contains(g.json, R"("buffers":[{"byteLength":240}])")) << g.json;
    ASSERT_EQ(g.bin.size(), 8u * 12u + 36u * 4u);
    for (std::size_t v = 0; v < 8; ++v)
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(std::bit_cast<float>(u32(g.bin, v * 12 + std::size_t(a) * 4)), mesh.vertices[v][a]);
    for (std::size_t t = 0; t < 12; ++t)
        for (int i = 0; i < 3; ++i) EXPECT_EQ(u32(g.bin, 96 + t * 12 + std::size_t(i) * 4), mesh.triangles[t][i]);
}

TEST(GlbWriter, JsonChunkIsPaddedWithSpacesAndWholeFileIsAligned) {
    test::TempDir dir;
    Mesh mesh = test::cubeMesh(1.0f);
    for (int extra = 0; extra < 4; ++extra) {  // vary the JSON length through every remainder mod 4
        mesh.vertices[0].x = -1.0f - 0.1f * float(extra);
        const std::string path = dir.file(std::to_string(extra) + ".glb");
        writeGlb(mesh, path);
        const std::string bytes = test::readFile(path);
        EXPECT_EQ(bytes.size() % 4, 0u);
        const Glb g = parseGlb(bytes);
        EXPECT_TRUE(balanced(g.json));
        const std::size_t end = g.json.find_last_of('}');
        EXPECT_EQ(g.json.find_first_not_of(' ', end + 1), std::string::npos) << "padding must be spaces";
    }
}

TEST(GlbWriter, EmptyMeshGivesAValidFileWithoutBuffer) {
    test::TempDir dir;
    const std::string path = dir.file("empty.glb");
    writeGlb(Mesh{}, path);
    const Glb g = parseGlb(test::readFile(path));
    EXPECT_FALSE(g.hasBin);
    EXPECT_TRUE(balanced(g.json));
    EXPECT_FALSE(contains(g.json, "buffers"));
    EXPECT_FALSE(contains(g.json, "accessors"));
}

TEST(GlbWriter, BadMeshOrUnwritablePathThrowsAndLeavesNoFile) {
    test::TempDir dir;
    Mesh bad = test::cubeMesh(1.0f);
    bad.triangles[3][1] = 8;
    EXPECT_THROW(writeGlb(bad, dir.file("bad.glb")), InputError);
    Mesh nan = test::cubeMesh(1.0f);
    nan.vertices[2].y = std::nanf("");
    EXPECT_THROW(writeGlb(nan, dir.file("nan.glb")), InputError);
    EXPECT_THROW(writeGlb(test::cubeMesh(1.0f), dir.file("no/such/folder/m.glb")), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "no file or temporary left behind";
}

}  // namespace
}  // namespace shapevo
