// Textured grammars through the command line: `shapevo sample` writes a textured OBJ with its MTL
// and the image beside it, and a GLB with the image embedded, for a CastleMaker rule file's
// add_texture too; a run writes best.obj, best.mtl, the image and best.glb into its folder,
// records the texture among its inputs and resumes, and a texture named like one of its outputs
// (curve.png) takes the next free name; a missing texture file is exit 2 with
// file:line:column naming it, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

const char* kWall =
    "start S\n"
    "rule S {\n"
    "  param w = uniform(0.6, 1.4)\n"
    "  size (w, 1, 0.4)\n"
    "  texture bricks \"bricks.png\" (w * 2, 2)\n"
    "  split x { ~1: { box } | ~1: { cylinder } }\n"
    "  child S prob 0.3\n"
    "}\n";

void copyBricks(const TempDir& dir) { fs::copy_file(sourcePath("tests/data/bricks.png"), dir.file("bricks.png")); }

TEST(TextureCli, SampleWritesTheImageBesideTheObjAndEmbedsItInTheGlb) {
    TempDir dir;
    copyBricks(dir);
    writeFile(dir.file("wall.grammar"), kWall);
    fs::create_directory(dir.path() / "out");
    const auto r = runShapevo("sample " + dir.file("wall.grammar") + " --seed 3 -o " + dir.file("out/m.obj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readFile(dir.file("out/m.mtl")).find("map_Kd bricks.png\n"), std::string::npos);
    EXPECT_NE(readFile(dir.file("out/m.obj")).find("\nvt "), std::string::npos);
    EXPECT_EQ(readFile(dir.file("out/bricks.png")), readFile(sourcePath("tests/data/bricks.png")));
    const auto g = runShapevo("sample " + dir.file("wall.grammar") + " --seed 3 -o " + dir.file("out/m.glb"));
    ASSERT_EQ(g.exitCode, 0) << g.output;
    const std::string glb = readFile(dir.file("out/m.glb"));
    EXPECT_NE(glb.find("\"mimeType\":\"image/png\""), std::string::npos);
    EXPECT_NE(glb.find(readFile(sourcePath("tests/data/bricks.png"))), std::string::npos) << "the PNG's bytes are in the GLB";
}

TEST(TextureCli, ARuleFilesAddTextureIsATexturedMaterial) {
    TempDir dir;
    copyBricks(dir);
    writeFile(dir.file("wall.rule"),
              "Lot = rect(-10, -3, 10, 3);\nLot -> extrude(8) {Block};\n"
              "Block -> add_texture(\"bricks\", \"bricks.png\", 10, 8) {Tex};\nTex -> subdiv(70, 30) {Low | High};\n"
              "Low -> insert_volume(1, 1, 1, 0, 0, 1);\nHigh -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    const auto r = runShapevo("sample " + dir.file("wall.rule") + " -o " + dir.file("m.obj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readFile(dir.file("m.mtl")).find("newmtl bricks\nKd 1 1 1\nmap_Kd bricks.png\n"), std::string::npos)
        << readFile(dir.file("m.mtl"));
    const std::string obj = readFile(dir.file("m.obj"));
    std::size_t v = 0, vt = 0;
    for (std::size_t at = obj.find("\nv "); at != std::string::npos; at = obj.find("\nv ", at + 1)) ++v;
    for (std::size_t at = obj.find("\nvt "); at != std::string::npos; at = obj.find("\nvt ", at + 1)) ++vt;
    EXPECT_GT(v, 0u);
    EXPECT_EQ(vt, v) << "one UV per vertex";
}

TEST(TextureCli, AMissingTextureIsExitTwoAtItsNameAndWritesNothing) {
    TempDir dir;
    writeFile(dir.file("wall.grammar"), kWall);
    const auto r = runShapevo("sample " + dir.file("wall.grammar") + " -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(dir.file("wall.grammar") + ":5:18: cannot open texture 'bricks.png': no such file"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    EXPECT_FALSE(fs::exists(dir.file("m.mtl")));
}

TEST(TextureCli, ARunWritesTheTexturedBestModelAndResumes) {
    TempDir dir;
    copyBricks(dir);
    const std::string cfg = test::configWithGrammar(dir, kWall, "wall");
    const std::string small = " --set ga.population=16 --set ga.elitism=2 -q";
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("r") + " --set ga.generations=2" + small);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readFile(dir.file("r/best.mtl")).find("map_Kd bricks.png"), std::string::npos);
    EXPECT_EQ(readFile(dir.file("r/bricks.png")), readFile(sourcePath("tests/data/bricks.png")));
    EXPECT_NE(readFile(dir.file("r/best.glb")).find("\"TEXCOORD_0\""), std::string::npos);
    const auto again = runShapevo("resume " + dir.file("r") + " --generations 3 -q");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_FALSE(fs::exists(dir.file("r/bricks_2.png"))) << "the same image again: no second copy";
    // a changed texture is a changed input, as a changed mesh is
    writeFile(dir.file("bricks.png"), readFile(sourcePath("docs/figures/grammar/roofs.png")));
    const auto changed = runShapevo("resume " + dir.file("r") + " --generations 4 -q");
    EXPECT_EQ(changed.exitCode, 2) << changed.output;
    std::string why = "texture ";  // built step by step: GCC 12 warns (-Wrestrict) on literal + string
    why += fs::absolute(dir.file("bricks.png")).lexically_normal().string();
    why += " changed";
    EXPECT_NE(changed.output.find(why), std::string::npos) << changed.output;
}

TEST(TextureCli, ARunsTextureNamedLikeAnOutputTakesTheNextFreeNameAndTheOutputKeepsItsOwn) {
    // The run's outputs are written side by side; the textured OBJ comes after all of them, so its
    // image never takes curve.png (nor is replaced by the plot).
    TempDir dir;
    fs::copy_file(sourcePath("tests/data/bricks.png"), dir.file("curve.png"));
    std::string grammar = kWall;
    grammar.replace(grammar.find("\"bricks.png\""), 12, "\"curve.png\"");
    const std::string cfg = test::configWithGrammar(dir, grammar, "wall");
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("r") + " --set ga.generations=2 --set ga.population=16 "
                              "--set ga.elitism=2 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readFile(dir.file("r/best.mtl")).find("map_Kd curve_2.png"), std::string::npos) << readFile(dir.file("r/best.mtl"));
    EXPECT_EQ(readFile(dir.file("r/curve_2.png")), readFile(sourcePath("tests/data/bricks.png")));
    EXPECT_NE(readFile(dir.file("r/curve.png")), readFile(sourcePath("tests/data/bricks.png"))) << "curve.png is the plot";
}

}  // namespace
}  // namespace shapevo
