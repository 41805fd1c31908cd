// Pictures end to end: `shapevo render` draws a mesh file, a run folder or a checkpoint file at
// the size and views asked for; every run writes best.png, which is what `render RUN_DIR`
// draws; `sample --count N -o sheet.png` writes one contact sheet; an existing output, a bad
// --size or --view, or a wrong extension is exit 2 with nothing written. A texture image named
// best.png takes another name beside best.obj (best.png is written first).
#include <gtest/gtest.h>

#include <filesystem>

#include "../image/png_read.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

/// The size of PNG `path`, or 0 x 0 if it cannot be read.
std::pair<int, int> pngSize(const std::string& path) {
    bool ok = false;
    const test::RgbaImage image = test::readPngRgba(path, ok);
    return {image.width, image.height};
}

TEST(RenderCommand, DrawsAMeshFileAtTheSizeAndViewsAskedFor) {
    TempDir dir;
    writeFile(dir.file("cube.obj"), kCubeObj);
    auto r = runShapevo("render " + dir.file("cube.obj") + " -o " + dir.file("a.png") + " --size 120x90");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("wrote " + dir.file("a.png") + " (120x90, three-quarter view of 12 triangles"), std::string::npos) << r.output;
    EXPECT_EQ(pngSize(dir.file("a.png")), std::pair(120, 90));
    r = runShapevo("render " + dir.file("cube.obj") + " -o " + dir.file("b.png") + " --size 40x30 --view three");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pngSize(dir.file("b.png")), std::pair(120, 30));
    r = runShapevo("render " + dir.file("cube.obj") + " -o " + dir.file("c.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pngSize(dir.file("c.png")), std::pair(800, 600)) << "the default size";
    r = runShapevo("render " + dir.file("cube.obj") + " -o " + dir.file("d.png"));
    EXPECT_EQ(readFile(dir.file("c.png")), readFile(dir.file("d.png"))) << "the same model, the same bytes";
}

TEST(RenderCommand, EveryRunWritesBestPngAndRenderDrawsTheRunsBestModel) {
    TempDir dir;
    const auto run = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("run") +
                                " --set ga.population=10 --set ga.generations=2 --set ga.elitism=2 -q");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_EQ(pngSize(dir.file("run/best.png")), std::pair(800, 600));
    auto r = runShapevo("render " + dir.file("run") + " -o " + dir.file("again.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("best model: island 0"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(dir.file("again.png")), readFile(dir.file("run/best.png")));
    // a checkpoint file stands for its checkpoint
    std::string checkpoint;
    for (const auto& e : fs::directory_iterator(dir.file("run")))
        if (e.path().filename().string().rfind("checkpoint-", 0) == 0) checkpoint = e.path().string();
    ASSERT_FALSE(checkpoint.empty());
    r = runShapevo("render " + checkpoint + "/run.h5 -o " + dir.file("top.png") + " --view top --size 64x48");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pngSize(dir.file("top.png")), std::pair(64, 48));
}

TEST(RenderCommand, ATextureNamedBestPngDoesNotReplaceTheRunsPicture) {
    TempDir dir;
    fs::copy_file(sourcePath("tests/data/bricks.png"), dir.file("best.png"));
    const std::string cfg = test::configWithGrammar(
        dir, "start S\nrule S {\n  size (1, 1, 0.4)\n  texture bricks \"best.png\" (2, 2)\n  box\n}\n", "wall");
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("r") + " --set ga.population=12 --set ga.generations=1 --set ga.elitism=2 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pngSize(dir.file("r/best.png")), std::pair(800, 600)) << "the picture";
    EXPECT_NE(readFile(dir.file("r/best.mtl")).find("map_Kd best_2.png"), std::string::npos) << readFile(dir.file("r/best.mtl"));
    EXPECT_EQ(readFile(dir.file("r/best_2.png")), readFile(sourcePath("tests/data/bricks.png"))) << "the texture, beside it";
}

TEST(RenderCommand, RefusesAnExistingOutputAndBadOptionsWithExitTwo) {
    TempDir dir;
    writeFile(dir.file("cube.obj"), kCubeObj);
    writeFile(dir.file("taken.png"), "mine");
    const std::string cube = dir.file("cube.obj");
    struct Case {
        std::string args, says;
    };
    for (const Case& c : {Case{"-o " + dir.file("taken.png"), "already exists"},
                          Case{"-o " + dir.file("v.png") + " --size 800", "--size"},
                          Case{"-o " + dir.file("v.png") + " --size 0x600", "--size"},
                          Case{"-o " + dir.file("v.png") + " --size axb", "--size"},
                          Case{"-o " + dir.file("v.png") + " --view iso", "--view"},
                          Case{"-o " + dir.file("v.jpg"), "-o"}}) {
        const auto r = runShapevo("render " + cube + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << ": " << r.output;
    }
    const auto missing = runShapevo("render " + dir.file("nope.obj") + " -o " + dir.file("v.png"));
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("nope.obj"), std::string::npos) << missing.output;
    const auto noRun = runShapevo("render " + dir.path().string() + " -o " + dir.file("v.png"));
    EXPECT_EQ(noRun.exitCode, 2) << noRun.output;
    EXPECT_EQ(readFile(dir.file("taken.png")), "mine");
    EXPECT_FALSE(fs::exists(dir.file("v.png")));
}

const char* kAB = "start S\nrule S { box child A prob 0.5 child B prob 0.5 }\nrule A { box }\nrule B { box }\n";

TEST(SampleSheet, CountModelsGoIntoOneContactSheet) {
    TempDir dir;
    writeFile(dir.file("ab.grammar"), kAB);
    auto r = runShapevo("sample " + dir.file("ab.grammar") + " --seed 5 --count 4 -o " + dir.file("sheet.png") + " --genome " +
                        dir.file("g.genome"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("(seed 8) -> " + dir.file("sheet.png") + " tile 4"), std::string::npos) << r.output;
    EXPECT_EQ(pngSize(dir.file("sheet.png")), std::pair(2 * 260 + 4, 2 * 260 + 4)) << "2 x 2 tiles of 256 x 256";
    EXPECT_FALSE(fs::exists(dir.file("sheet-001.png")));
    EXPECT_TRUE(fs::exists(dir.file("g-004.genome")));
    r = runShapevo("sample " + dir.file("ab.grammar") + " --count 3 --size 64x48 -o " + dir.file("small.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pngSize(dir.file("small.png")), std::pair(2 * 68 + 4, 2 * 52 + 4));
    // refused: the sheet exists; --size without a sheet; a bad --size
    for (const std::string& args : {"--count 2 -o " + dir.file("sheet.png"), "--size 64x48 -o " + dir.file("m.obj"),
                                    "--count 2 --size 64 -o " + dir.file("other.png")}) {
        r = runShapevo("sample " + dir.file("ab.grammar") + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.output;
    }
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    EXPECT_FALSE(fs::exists(dir.file("other.png")));
}

}  // namespace
}  // namespace shapevo
