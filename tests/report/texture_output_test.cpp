// OBJ and PLY writers with textures: a textured model's OBJ has one `vt` per vertex and faces
// `f a/a b/b c/c`, its MTL `map_Kd FILE.png` for the textured material, and the image is copied
// next to them — an identical file there is used, another one is never replaced (the copy takes
// the next free name), and a model that cannot be written leaves no copy behind. The PLY has
// white vertex colours on textured primitives and no UVs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "geometry/tessellation.hpp"
#include "grammar/front_ends.hpp"
#include "mesh/mesh_reader.hpp"
#include "report/model_writer.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

/// A red box and a split, textured wall, derived from a grammar in tests/data.
Mesh texturedModel() {
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  color (1, 0, 0) box\n  translate (3, 0, 0) size (4, 2, 1)\n"
        "  texture \"wall bricks\" \"bricks.png\" (2, 1)\n  split x { ~1: { box } | ~1: { cylinder } }\n}\n",
        test::sourcePath("tests/data/wall.grammar"));
    Rng rng(1);
    Chromosome c;
    plantRoot(g, c, rng);
    Geometry geometry;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geometry, scratch), DeriveStatus::Complete);
    return tessellate(geometry);  // holds copies of what it needs from the grammar
}


std::size_t countPrefix(const std::vector<std::string>& ls, const std::string& prefix) {
    return std::size_t(std::count_if(ls.begin(), ls.end(), [&](const std::string& l) { return l.rfind(prefix, 0) == 0; }));
}

const std::string kBricks = test::sourcePath("tests/data/bricks.png");

TEST(ObjTexture, VtLinesFacesWithUvIndicesAndMapKdWithTheImageCopied) {
    test::TempDir dir;
    const Mesh mesh = texturedModel();
    ASSERT_EQ(mesh.textures.size(), 1u);
    writeObj(mesh, dir.file("m.obj"));
    const auto obj = test::splitLines(test::readFile(dir.file("m.obj")));
    EXPECT_EQ(countPrefix(obj, "v "), mesh.vertices.size());
    EXPECT_EQ(countPrefix(obj, "vt "), mesh.vertices.size()) << "one UV per vertex";
    EXPECT_EQ(countPrefix(obj, "f "), mesh.triangles.size());
    std::size_t vt = 0;
    for (const std::string& l : obj) {
        std::istringstream in(l);
        std::string key;
        in >> key;
        if (key == "vt") {
            float u, v;
            in >> u >> v;
            EXPECT_NEAR(u, mesh.uvs[vt].x, 1e-5f);
            EXPECT_NEAR(v, mesh.uvs[vt].y, 1e-5f);
            ++vt;
        }
        if (key != "f") continue;
        for (std::string corner; in >> corner;) {
            const auto slash = corner.find('/');
            ASSERT_NE(slash, std::string::npos) << l;
            EXPECT_EQ(corner.substr(0, slash), corner.substr(slash + 1)) << "vertex and UV share an index: " << l;
        }
    }
    const auto mtl = test::splitLines(test::readFile(dir.file("m.mtl")));
    const auto textured = std::find(mtl.begin(), mtl.end(), "newmtl wall_bricks");
    ASSERT_NE(textured, mtl.end());
    EXPECT_EQ(*(textured + 1), "Kd 1 1 1");
    EXPECT_EQ(*(textured + 2), "map_Kd bricks.png");
    EXPECT_EQ(countPrefix(mtl, "map_Kd"), 1u) << "the red box has no texture";
    EXPECT_EQ(test::readFile(dir.file("bricks.png")), test::readFile(kBricks)) << "the image is copied";
    const Mesh back = readMesh(dir.file("m.obj"));  // the reader takes `f a/b` faces
    EXPECT_EQ(back.triangles.size(), mesh.triangles.size());
}

TEST(ObjTexture, AnIdenticalImageIsUsedAndADifferentOneIsNeverReplaced) {
    test::TempDir dir;
    const Mesh mesh = texturedModel();
    writeObj(mesh, dir.file("a.obj"));
    writeObj(mesh, dir.file("b.obj"));
    EXPECT_FALSE(fs::exists(dir.file("bricks_2.png"))) << "the same bytes: used as they are";
    fs::create_directory(dir.path() / "c");
    test::writeFile((dir.path() / "c" / "bricks.png").string(), "someone else's picture");
    test::writeFile((dir.path() / "c" / "bricks_2.png").string(), "and another one");
    writeObj(mesh, (dir.path() / "c" / "m.obj").string(), Replace::Never);
    EXPECT_EQ(test::readFile((dir.path() / "c" / "bricks.png").string()), "someone else's picture");
    EXPECT_EQ(test::readFile((dir.path() / "c" / "bricks_2.png").string()), "and another one");
    EXPECT_EQ(test::readFile((dir.path() / "c" / "bricks_3.png").string()), test::readFile(kBricks));
    const auto mtl = test::splitLines(test::readFile((dir.path() / "c" / "m.mtl").string()));
    EXPECT_NE(std::find(mtl.begin(), mtl.end(), "map_Kd bricks_3.png"), mtl.end());
}

TEST(ObjTexture, ARefusedModelLeavesNoImageBehind) {
    test::TempDir dir;
    test::writeFile(dir.file("m.mtl"), "mine");
    EXPECT_THROW(writeObj(texturedModel(), dir.file("m.obj"), Replace::Never), InputError);
    EXPECT_FALSE(fs::exists(dir.file("bricks.png")));
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    fs::remove(dir.file("m.mtl"));
    fs::create_directory(dir.path() / "m.obj");  // the image and the MTL are written, then the OBJ fails
    EXPECT_THROW(writeObj(texturedModel(), dir.file("m.obj")), InputError);
    EXPECT_FALSE(fs::exists(dir.file("bricks.png"))) << "the copy it made is removed again";
}

TEST(PlyTexture, TexturedPrimitivesAreWhite) {
    test::TempDir dir;
    const Mesh mesh = texturedModel();
    writePly(mesh, dir.file("m.ply"));
    const std::string bytes = test::readFile(dir.file("m.ply"));
    EXPECT_EQ(bytes.find("property float u"), std::string::npos);
    const std::size_t body = bytes.find("end_header\n") + 11;
    ASSERT_EQ(bytes.size(), body + mesh.vertices.size() * 15 + mesh.triangles.size() * 13);
    std::vector<bool> white(mesh.vertices.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (mesh.materials[mesh.triangleMaterials[t]].texture >= 0)
            for (std::uint32_t v : mesh.triangles[t]) white[v] = true;
    ASSERT_GT(std::count(white.begin(), white.end(), true), 0);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const char* rgb = bytes.data() + body + v * 15 + 12;
        if (white[v])
            for (int c = 0; c < 3; ++c) EXPECT_EQ(std::uint8_t(rgb[c]), 255) << "vertex " << v;
        else
            EXPECT_EQ(std::uint8_t(rgb[0]), 255) << "the red box";
    }
}

}  // namespace
}  // namespace shapevo
