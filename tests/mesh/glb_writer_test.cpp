// GLB writer: the file parses back as binary glTF 2.0 (header, aligned JSON and BIN chunks) and
// its buffer holds exactly the mesh's positions and indices, with the counts and bounds in JSON.
// With materials the JSON chunk, parsed as JSON, holds one glTF material (name, linear
// baseColorFactor) per mesh material and one primitive per used material, whose indices in the
// buffer are exactly that material's triangles.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "cube_mesh.hpp"
#include "glb_file.hpp"
#include "json_value.hpp"
#include "mesh/glb_writer.hpp"
#include "base/input_error.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::Glb;
using test::parseGlb;
using test::u32;

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

/// Appends `part` to `into` with every triangle of material `material`.
void appendPart(Mesh& into, const Mesh& part, std::uint32_t material) {
    const auto base = std::uint32_t(into.vertices.size());
    into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& t : part.triangles) {
        into.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        into.triangleMaterials.push_back(material);
    }
}

/// Three boxes, the first and last of material 0 ("paint", orange), the middle of material 1
/// ("color_3366ff"); a third material nothing uses when `unused` is set.
Mesh colouredBoxes(bool unused = false) {
    Mesh m;
    m.materials = {{"paint", {1.0f, 0.25f, 0.0f}}, {"color_3366ff", {0.0331f, 0.1329f, 1.0f}}};
    if (unused) m.materials.push_back({"spare", {0.5f, 0.5f, 0.5f}});
    appendPart(m, test::boxMesh({0, 0, 0}, {1, 1, 1}), 0);
    appendPart(m, test::boxMesh({2, 0, 0}, {3, 2, 1}), 1);
    appendPart(m, test::boxMesh({-2, -1, 0}, {-1, 0, 4}), 0);
    return m;
}

TEST(GlbWriter, PlainMeshJsonParsesWithOnePrimitiveAndNoMaterial) {
    test::TempDir dir;
    const std::string path = dir.file("plain.glb");
    writeGlb(test::cubeMesh(1.0f), path);
    const test::Json json = test::parseJson(parseGlb(test::readFile(path)).json);
    EXPECT_FALSE(json.has("materials"));
    const test::Json& primitives = json["meshes"][0]["primitives"];
    ASSERT_EQ(primitives.size(), 1u);
    EXPECT_FALSE(primitives[0].has("material"));
    EXPECT_EQ(primitives[0]["indices"].number, 1.0);
    EXPECT_EQ(json["accessors"][1]["count"].number, 36.0);
    EXPECT_FALSE(json["accessors"][1].has("byteOffset"));
}

/// The index accessor `a`'s indices, read from the BIN chunk as glTF locates them.
std::vector<std::uint32_t> accessorIndices(const test::Json& json, const std::string& bin, std::size_t a) {
    const test::Json& accessor = json["accessors"][a];
    EXPECT_EQ(accessor["componentType"].number, 5125.0) << "unsigned int";
    EXPECT_EQ(accessor["type"].string, "SCALAR");
    const test::Json& view = json["bufferViews"][std::size_t(accessor["bufferView"].number)];
    EXPECT_EQ(view["target"].number, 34963.0) << "ELEMENT_ARRAY_BUFFER";
    const std::size_t offset = accessor.has("byteOffset") ? std::size_t(accessor["byteOffset"].number) : 0;
    const std::size_t start = std::size_t(view["byteOffset"].number) + offset;
    const auto count = std::size_t(accessor["count"].number);
    EXPECT_EQ(offset % 4, 0u) << "accessor aligned to its component size";
    EXPECT_LE(offset + count * 4, std::size_t(view["byteLength"].number)) << "accessor inside its view";
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(u32(bin, start + 4 * i));
    return out;
}

TEST(GlbWriter, EachMaterialBecomesANamedGltfMaterialWithItsLinearColourAndItsOwnPrimitive) {
    test::TempDir dir;
    const Mesh mesh = colouredBoxes();
    const std::string path = dir.file("coloured.glb");
    writeGlb(mesh, path);
    const Glb glb = parseGlb(test::readFile(path));
    const test::Json json = test::parseJson(glb.json);
    ASSERT_EQ(json["materials"].size(), 2u);
    for (std::size_t m = 0; m < 2; ++m) {
        const test::Json& material = json["materials"][m];
        EXPECT_EQ(material["name"].string, mesh.materials[m].name);
        const test::Json& factor = material["pbrMetallicRoughness"]["baseColorFactor"];
        ASSERT_EQ(factor.size(), 4u);
        for (std::size_t a = 0; a < 3; ++a)
            EXPECT_EQ(float(factor[a].number), mesh.materials[m].color[int(a)]) << "linear, exact";
        EXPECT_EQ(factor[3].number, 1.0);
        EXPECT_EQ(material["pbrMetallicRoughness"]["metallicFactor"].number, 0.0);
    }
    const test::Json& primitives = json["meshes"][0]["primitives"];
    ASSERT_EQ(primitives.size(), 2u) << "one primitive per material";
    EXPECT_EQ(json["accessors"][0]["count"].number, double(mesh.vertices.size()));
    std::size_t indices = 0;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        EXPECT_EQ(primitives[p]["attributes"]["POSITION"].number, 0.0) << "all share the positions";
        EXPECT_EQ(primitives[p]["mode"].number, 4.0);
        const auto material = std::uint32_t(primitives[p]["material"].number);
        EXPECT_EQ(material, p) << "primitives in material order";
        std::vector<std::uint32_t> expected;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            if (mesh.triangleMaterials[t] == material)
                expected.insert(expected.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
        const auto accessor = std::size_t(primitives[p]["indices"].number);
        EXPECT_EQ(accessorIndices(json, glb.bin, accessor), expected) << "material " << material;
        indices += expected.size();
    }
    EXPECT_EQ(indices, mesh.triangles.size() * 3);
    EXPECT_EQ(json["bufferViews"][1]["byteLength"].number, double(indices * 4));
    EXPECT_EQ(json["buffers"][0]["byteLength"].number, double(glb.bin.size()));
}

TEST(GlbWriter, MaterialWithoutTrianglesIsListedButHasNoPrimitive) {
    test::TempDir dir;
    const std::string path = dir.file("unused.glb");
    writeGlb(colouredBoxes(true), path);
    const test::Json json = test::parseJson(parseGlb(test::readFile(path)).json);
    EXPECT_EQ(json["materials"].size(), 3u);
    EXPECT_EQ(json["materials"][2]["name"].string, "spare");
    const test::Json& primitives = json["meshes"][0]["primitives"];
    ASSERT_EQ(primitives.size(), 2u);
    for (std::size_t p = 0; p < 2; ++p) EXPECT_NE(primitives[p]["material"].number, 2.0);
}

TEST(GlbWriter, InconsistentMaterialsThrowAndLeaveNoFile) {
    test::TempDir dir;
    Mesh missing = colouredBoxes();
    missing.triangleMaterials.pop_back();
    EXPECT_THROW(writeGlb(missing, dir.file("a.glb")), InputError);
    Mesh outOfRange = colouredBoxes();
    outOfRange.triangleMaterials[4] = 2;
    EXPECT_THROW(writeGlb(outOfRange, dir.file("b.glb")), InputError);
    Mesh twice = colouredBoxes();
    twice.materials[1].name = "paint";
    EXPECT_THROW(writeGlb(twice, dir.file("c.glb")), InputError);
    Mesh quote = colouredBoxes();
    quote.materials[0].name = "a\"b";
    EXPECT_THROW(writeGlb(quote, dir.file("d.glb")), InputError);
    Mesh bright = colouredBoxes();
    bright.materials[0].color.g = 1.5f;
    EXPECT_THROW(writeGlb(bright, dir.file("e.glb")), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(GlbWriter, NeverReplaceKeepsAnExistingFile) {
    test::TempDir dir;
    const std::string path = test::writeFile(dir, "kept.glb", "mine");
    EXPECT_THROW(writeGlb(colouredBoxes(), path, Replace::Never), InputError);
    EXPECT_EQ(test::readFile(path), "mine");
    writeGlb(colouredBoxes(), dir.file("new.glb"), Replace::Never);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2) << "no temporary left behind";
}

}  // namespace
}  // namespace shapevo
