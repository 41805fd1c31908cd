// Model files as `sample` and `export` write them (writeModelFile): every mesh format carries a
// coloured model's looks (OBJ + MTL, PLY vertex colours, GLB materials), and with
// Replace::Never an existing file is never overwritten, the MTL an OBJ would bring included.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/input_error.hpp"
#include "report/model_writer.hpp"
#include "run/model_export.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

Geometry twoColourBoxes() {
    Geometry g;
    Primitive a, b;
    b.centre = {2.0f, 0.0f, 0.0f};
    g.primitives = {a, b};
    g.appearance = {{{1, 0, 0}, 0}, {{0, 0, 1}, 0}};
    return g;
}

TEST(ModelFile, EveryMeshFormatCarriesTheColours) {
    test::TempDir dir;
    const Geometry g = twoColourBoxes();
    for (const char* format : {"obj", "ply", "glb"})
        writeModelFile(g, format, dir.file(std::string("m.") + format), Replace::Never);
    const std::string mtl = test::readFile(dir.file("m.mtl"));
    EXPECT_NE(mtl.find("newmtl color_ff0000\nKd 1 0 0\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("newmtl color_0000ff\nKd 0 0 1\n"), std::string::npos) << mtl;
    EXPECT_NE(test::readFile(dir.file("m.obj")).find("mtllib m.mtl\n"), std::string::npos);
    EXPECT_NE(test::readFile(dir.file("m.ply")).find("property uchar red\n"), std::string::npos);
    EXPECT_NE(test::readFile(dir.file("m.glb")).find(R"("materials":[{"name":"color_ff0000")"), std::string::npos);
}

TEST(ModelFile, NeverReplaceRefusesTheMtlOfAColouredObjAndWritesNothing) {
    test::TempDir dir;
    test::writeFile(dir.file("m.mtl"), "mine");
    EXPECT_THROW(writeModelFile(twoColourBoxes(), "obj", dir.file("m.obj"), Replace::Never), InputError);
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    EXPECT_EQ(test::readFile(dir.file("m.mtl")), "mine");
}

TEST(ModelFile, PlainObjWritesNoMtl) {
    test::TempDir dir;
    Geometry g = twoColourBoxes();
    g.appearance.clear();
    writeModelFile(g, "obj", dir.file("m.obj"), Replace::Never);
    EXPECT_FALSE(fs::exists(dir.file("m.mtl")));
}

}  // namespace
}  // namespace shapevo
