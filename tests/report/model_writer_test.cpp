// OBJ and PLY writers with colours: a coloured model's OBJ names an MTL written next to it (one
// newmtl and Kd per material, read back to the written precision), its faces are grouped under
// one usemtl per material and still read back through shapevo's own mesh reader; the PLY's
// vertices carry the sRGB bytes of their primitive's colour, read back from the binary records.
// Replace::Never refuses an existing OBJ or MTL without writing either file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "base/input_error.hpp"
#include "geometry/tessellation.hpp"
#include "mesh/mesh_material.hpp"
#include "mesh/mesh_reader.hpp"
#include "report/model_writer.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kNames = {"", "steel"};

Primitive at(PrimitiveKind kind, float x) {
    Primitive p;
    p.kind = kind;
    p.centre = {x, 0.5f, -1.0f};
    p.half = {0.5f, 1.0f, 0.75f};
    return p;
}

/// Orange box, steel cylinder, orange cone (the box's look again), darker steel sphere.
Geometry colouredModel() {
    Geometry g;
    g.materialNames = &kNames;
    g.primitives = {at(PrimitiveKind::Box, 0), at(PrimitiveKind::Cylinder, 2), at(PrimitiveKind::Cone, 4),
                    at(PrimitiveKind::Sphere, 6)};
    g.appearance = {{{1.0f, 0.5f, 0.0f}, 0}, {{0.2f, 0.4f, 0.6f}, 1}, {{1.0f, 0.5f, 0.0f}, 0}, {{0.1f, 0.1f, 0.1f}, 1}};
    return g;
}


struct ObjFile {
    std::string mtllib;
    std::vector<glm::vec3> vertices;
    std::vector<std::string> usemtl;                                  ///< in file order
    std::map<std::string, std::vector<std::array<std::uint32_t, 3>>> faces;  ///< by usemtl, 0-based
    std::size_t faceCount = 0;
};

ObjFile readObj(const std::string& path) {
    ObjFile f;
    std::string current;
    for (const std::string& l : test::splitLines(test::readFile(path))) {
        std::istringstream in(l);
        std::string key;
        in >> key;
        if (key == "mtllib") in >> f.mtllib;
        if (key == "usemtl") f.usemtl.push_back(current = l.substr(7));
        if (key == "v") {
            glm::vec3 v;
            in >> v.x >> v.y >> v.z;
            f.vertices.push_back(v);
        }
        if (key == "f") {
            std::array<std::uint32_t, 3> t;
            in >> t[0] >> t[1] >> t[2];
            for (auto& i : t) --i;
            f.faces[current].push_back(t);
            ++f.faceCount;
        }
    }
    return f;
}

/// newmtl name -> Kd, in file order.
std::vector<std::pair<std::string, glm::vec3>> readMtl(const std::string& path) {
    std::vector<std::pair<std::string, glm::vec3>> out;
    for (const std::string& l : test::splitLines(test::readFile(path))) {
        std::istringstream in(l);
        std::string key;
        in >> key;
        if (key == "newmtl") out.push_back({l.substr(7), glm::vec3(-1.0f)});
        if (key == "Kd") {
            EXPECT_FALSE(out.empty()) << "Kd before newmtl";
            if (!out.empty()) in >> out.back().second.x >> out.back().second.y >> out.back().second.z;
        }
    }
    return out;
}

TEST(ObjWriter, ColouredModelWritesAnMtlNextToTheObjWithOneNewmtlAndKdPerAppearance) {
    test::TempDir dir;
    const Mesh mesh = meshOf(colouredModel());
    ASSERT_EQ(mesh.materials.size(), 3u);
    writeObj(mesh, dir.file("model.obj"));
    ASSERT_TRUE(fs::exists(dir.file("model.mtl")));
    const ObjFile obj = readObj(dir.file("model.obj"));
    EXPECT_EQ(obj.mtllib, "model.mtl") << "named relative to the OBJ";
    const auto mtl = readMtl(dir.file("model.mtl"));
    ASSERT_EQ(mtl.size(), mesh.materials.size());
    for (std::size_t m = 0; m < mtl.size(); ++m) {
        EXPECT_EQ(mtl[m].first, mesh.materials[m].name);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(mtl[m].second[a], mesh.materials[m].color[a], 1e-6f) << "linear Kd";
    }
    EXPECT_EQ(mtl[0].first, "color_ffbc00");
    EXPECT_EQ(mtl[1].first, "steel");
    EXPECT_EQ(mtl[2].first, "steel_2");
}

TEST(ObjWriter, FacesAreGroupedUnderOneUsemtlPerMaterialInMeshOrder) {
    test::TempDir dir;
    const Mesh mesh = meshOf(colouredModel());
    writeObj(mesh, dir.file("m.obj"));
    const ObjFile obj = readObj(dir.file("m.obj"));
    std::vector<std::string> names;
    for (const MeshMaterial& m : mesh.materials) names.push_back(m.name);
    EXPECT_EQ(obj.usemtl, names) << "each material once, in order";
    EXPECT_EQ(obj.faceCount, mesh.triangles.size());
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        std::vector<std::array<std::uint32_t, 3>> expected;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            if (mesh.triangleMaterials[t] == m) expected.push_back(mesh.triangles[t]);
        EXPECT_EQ(obj.faces.at(names[m]), expected) << names[m];
    }
    ASSERT_EQ(obj.vertices.size(), mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(obj.vertices[v][a], mesh.vertices[v][a], 1e-5f);
}

TEST(ObjWriter, ColouredObjReadsBackThroughTheMeshReaderWithTheSameTriangles) {
    test::TempDir dir;
    const Mesh mesh = meshOf(colouredModel());
    writeObj(mesh, dir.file("m.obj"));
    const Mesh back = readMesh(dir.file("m.obj"));
    EXPECT_EQ(back.vertices.size(), mesh.vertices.size());
    auto a = mesh.triangles, b = back.triangles;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << "the same faces, only regrouped";
}

TEST(ObjWriter, NeverReplaceRefusesAnExistingMtlAndWritesNoObj) {
    test::TempDir dir;
    test::writeFile(dir.file("m.mtl"), "mine");
    try {
        writeObj(meshOf(colouredModel()), dir.file("m.obj"), Replace::Never);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.file("m.mtl"));
        EXPECT_NE(std::string(e.what()).find("already exists"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    EXPECT_EQ(test::readFile(dir.file("m.mtl")), "mine");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 1) << "no temporary left behind";
}

TEST(ObjWriter, NeverReplaceRefusesAnExistingObjAndWritesNoMtl) {
    test::TempDir dir;
    test::writeFile(dir.file("m.obj"), "mine");
    EXPECT_THROW(writeObj(meshOf(colouredModel()), dir.file("m.obj"), Replace::Never), InputError);
    EXPECT_EQ(test::readFile(dir.file("m.obj")), "mine");
    EXPECT_FALSE(fs::exists(dir.file("m.mtl")));
}

TEST(ObjWriter, NeverReplaceWritesBothFilesWhenNeitherExists) {
    test::TempDir dir;
    writeObj(meshOf(colouredModel()), dir.file("m.obj"), Replace::Never);
    EXPECT_EQ(readObj(dir.file("m.obj")).mtllib, "m.mtl");
    EXPECT_EQ(readMtl(dir.file("m.mtl")).size(), 3u);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 2);
}

TEST(ObjWriter, AlwaysReplacesTheObjAndItsMtlTogether) {
    test::TempDir dir;
    writeObj(meshOf(colouredModel()), dir.file("best.obj"));
    Geometry other = colouredModel();
    other.appearance = {{{0, 1, 0}, 0}, {{0, 1, 0}, 0}, {{0, 1, 0}, 0}, {{0, 1, 0}, 0}};
    writeObj(meshOf(other), dir.file("best.obj"));
    const auto mtl = readMtl(dir.file("best.mtl"));
    ASSERT_EQ(mtl.size(), 1u);
    EXPECT_EQ(mtl[0].first, "color_00ff00");
    EXPECT_EQ(readObj(dir.file("best.obj")).usemtl, std::vector<std::string>{"color_00ff00"});
}

TEST(ObjWriter, MtlPathReplacesTheObjExtension) {
    EXPECT_EQ(mtlPathFor("out/m.obj"), "out/m.mtl");
    EXPECT_EQ(mtlPathFor("a.b/m.OBJ"), "a.b/m.mtl");
    EXPECT_EQ(mtlPathFor("m"), "m.mtl");
    EXPECT_EQ(mtlPathFor("/runs/x/best.obj"), "/runs/x/best.mtl");
}

TEST(ObjWriter, ColouredObjNamedLikeItsMtlIsRefused) {
    test::TempDir dir;
    EXPECT_THROW(writeObj(meshOf(colouredModel()), dir.file("m.MTL")), InputError);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

/// The PLY header's lines and the offset of the binary body.
std::pair<std::vector<std::string>, std::size_t> plyHeader(const std::string& bytes) {
    const std::size_t end = bytes.find("end_header\n");
    EXPECT_NE(end, std::string::npos);
    return {test::splitLines(bytes.substr(0, end + 10)), end + 11};
}

TEST(PlyWriter, HeaderDeclaresUcharRedGreenBlueAfterXyz) {
    test::TempDir dir;
    const Mesh mesh = meshOf(colouredModel());
    writePly(mesh, dir.file("m.ply"));
    const auto [header, body] = plyHeader(test::readFile(dir.file("m.ply")));
    const std::vector<std::string> vertexPart = {"element vertex " + std::to_string(mesh.vertices.size()),
                                                 "property float x", "property float y", "property float z",
                                                 "property uchar red", "property uchar green", "property uchar blue",
                                                 "element face " + std::to_string(mesh.triangles.size())};
    const auto at = std::find(header.begin(), header.end(), vertexPart.front());
    ASSERT_NE(at, header.end());
    EXPECT_TRUE(std::equal(vertexPart.begin(), vertexPart.end(), at));
}

TEST(PlyWriter, VertexColoursAreTheSrgbBytesOfTheirPrimitivesColourAndReadBack) {
    test::TempDir dir;
    const Geometry g = colouredModel();
    const Mesh mesh = meshOf(g);
    writePly(mesh, dir.file("m.ply"));
    const std::string bytes = test::readFile(dir.file("m.ply"));
    const std::size_t body = plyHeader(bytes).second;
    ASSERT_EQ(bytes.size(), body + mesh.vertices.size() * 15 + mesh.triangles.size() * 13);
    std::size_t v = 0;
    for (std::size_t p = 0; p < g.primitives.size(); ++p) {
        Mesh alone;
        appendSurface(g.primitives[p], nullptr, alone);
        const auto rgb = srgbBytes(g.appearance[p].color);
        for (std::size_t i = 0; i < alone.vertices.size(); ++i, ++v) {
            const char* record = bytes.data() + body + v * 15;
            float xyz[3];
            std::memcpy(xyz, record, 12);
            for (int a = 0; a < 3; ++a) EXPECT_EQ(xyz[a], mesh.vertices[v][a]) << "vertex " << v;
            for (int c = 0; c < 3; ++c) EXPECT_EQ(std::uint8_t(record[12 + c]), rgb[std::size_t(c)]) << "vertex " << v;
        }
    }
    EXPECT_EQ(v, mesh.vertices.size());
    EXPECT_EQ(srgbBytes(g.appearance[0].color), (std::array<std::uint8_t, 3>{255, 188, 0}));
    const Mesh back = readMesh(dir.file("m.ply"));  // the reader skips the colour properties
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(PlyWriter, NeverReplaceKeepsAnExistingFile) {
    test::TempDir dir;
    test::writeFile(dir.file("m.ply"), "mine");
    EXPECT_THROW(writePly(meshOf(colouredModel()), dir.file("m.ply"), Replace::Never), InputError);
    EXPECT_EQ(test::readFile(dir.file("m.ply")), "mine");
}

}  // namespace
}  // namespace shapevo
