// `shapevo target MESH --image CONFIG -o target.png` (issue 14, line 4): a box's shadow through
// an image config's shadow camera is its footprint, and the picture loads as that config's
// target (its pixel rule, the camera's size); a volume config (no camera), an existing output
// and a non-.png output are refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "../mesh/cube_mesh.hpp"
#include "../test_support.hpp"
#include "score/image/image_target.hpp"

namespace shapevo {
namespace {

using namespace test;

const char* kBoxObj =
    "v -0.93 0.5 -0.93\nv 0.93 0.5 -0.93\nv -0.93 2.5 -0.93\nv 0.93 2.5 -0.93\n"
    "v -0.93 0.5 0.93\nv 0.93 0.5 0.93\nv -0.93 2.5 0.93\nv 0.93 2.5 0.93\n"
    "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";

std::string shadowConfig(const TempDir& dir) {
    return writeFile(dir, "shadow.toml",
                     "[grammar]\nfile = \"" + sourcePath("grammars/tree.grammar") +
                         "\"\n[target]\nimage = \"shadow.png\"\n[camera]\nprojection = \"shadow\"\nwidth = 40\nheight = 40\n"
                         "light = [0.0, -1.0, 0.0]\nground_y = 0.0\nground_min = [-2.0, -2.0]\nground_max = [2.0, 2.0]\n");
}

TEST(TargetImageCli, BoxShadowIsItsFootprintAndLoadsAsTheConfigsTarget) {
    TempDir dir;
    const std::string mesh = writeFile(dir, "box.obj", kBoxObj);
    const std::string config = shadowConfig(dir);
    const CommandResult r = runShapevo("target " + mesh + " --image " + config + " -o " + dir.file("shadow.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("shadow covers 324 of 40 x 40 pixels"), std::string::npos) << r.output;
    const ImageTarget t = loadImageTarget(dir.file("shadow.png"), PixelRule{}, 40, 40);
    EXPECT_EQ(t.hitCount, 18u * 18u);  // pixel centres -0.85 .. 0.85 in x and z
    EXPECT_EQ(t.avoidCount, 1600u - 324u);
    EXPECT_TRUE(t.isHit(20, 20));
    EXPECT_FALSE(t.isHit(1, 20));
}

TEST(TargetImageCli, AVolumeConfigAndAnExistingOutputAreRefused) {
    TempDir dir;
    const std::string mesh = writeFile(dir, "box.obj", kBoxObj);
    const CommandResult volume = runShapevo("target " + mesh + " --image " + sourcePath("configs/spaceship.toml") + " -o " +
                                            dir.file("a.png"));
    EXPECT_EQ(volume.exitCode, 2) << volume.output;
    EXPECT_NE(volume.output.find("has no image target and camera"), std::string::npos) << volume.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));

    writeFile(dir, "taken.png", "mine");
    const CommandResult taken = runShapevo("target " + mesh + " --image " + shadowConfig(dir) + " -o " + dir.file("taken.png"));
    EXPECT_EQ(taken.exitCode, 2) << taken.output;
    EXPECT_NE(taken.output.find("already exists"), std::string::npos) << taken.output;
    EXPECT_EQ(readFile(dir.file("taken.png")), "mine");

    const CommandResult vdb = runShapevo("target " + mesh + " --image " + shadowConfig(dir) + " -o " + dir.file("b.vdb"));
    EXPECT_EQ(vdb.exitCode, 2) << vdb.output;
}

}  // namespace
}  // namespace shapevo
