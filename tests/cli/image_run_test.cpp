// End-to-end runs against image targets: the silhouette and shadow scenes write their overlay
// and silhouette IoU, resume like any run, and refuse bad image/camera set-ups with exit 2
// before creating anything.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

const std::string kSmallImage = " --set ga.population=30 --set ga.generations=6 --set ga.elitism=6 -q";

TEST(ImageRun, SketchAndLogoScenesWriteOverlayCurveAndSilhouetteIoU) {
    TempDir dir;
    for (const char* scene : {"tree-sketch", "tree-logo", "city-whale"}) {
        const std::string out = dir.file(scene);
        const auto r = runShapevo("run " + sourcePath(std::string("configs/") + scene + ".toml") + " --out " + out + kSmallImage);
        ASSERT_EQ(r.exitCode, 0) << scene << ": " << r.output;
        for (const char* f : {"best-overlay.png", "best.png", "best.glb", "best.obj", "curve.svg", "curve.png", "summary.json"})
            EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << scene << " " << f;
        const std::string summary = readFile(out + "/summary.json");
        EXPECT_NE(summary.find("\"silhouette_iou\": 0."), std::string::npos) << summary;
        EXPECT_EQ(summary.find("voxel_iou"), std::string::npos) << summary;
    }
}

TEST(ImageRun, ResumedImageRunEqualsTheUninterruptedOne) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/tree-logo.toml");
    const std::string base = " --set ga.population=30 --set ga.elitism=6 --set checkpoint.interval=3 -q";
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("whole") + " --set ga.generations=6" + base).exitCode, 0);
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("split") + " --set ga.generations=3" + base).exitCode, 0);
    const auto r = runShapevo("resume " + dir.file("split") + " --generations 6 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("split/best.genome")));
    EXPECT_EQ(test::curveWithoutTime(readFile(dir.file("whole/curve.csv"))),
              test::curveWithoutTime(readFile(dir.file("split/curve.csv"))));
}

TEST(ImageRun, ExportWritesTheOverlayAndRefusesVoxelsOfAnImageRun) {
    TempDir dir;
    ASSERT_EQ(runShapevo("run " + sourcePath("configs/tree-sketch.toml") + " --out " + dir.file("run") + kSmallImage).exitCode, 0);
    const auto png = runShapevo("export " + dir.file("run") + " --best -o " + dir.file("o.png"));
    EXPECT_EQ(png.exitCode, 0) << png.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("o.png")));
    const auto vdb = runShapevo("export " + dir.file("run") + " --best -o " + dir.file("o.vdb"));
    EXPECT_EQ(vdb.exitCode, 2) << vdb.output;
    EXPECT_NE(vdb.output.find("image target"), std::string::npos) << vdb.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.vdb")));
}

struct BadImageCase {
    const char* name;
    std::string overrides;
    const char* message;
};

TEST(ImageRun, BadCameraOrImageIsALocatedErrorAndCreatesNothing) {
    TempDir dir;
    test::writeFile(dir.file("empty.png"), "");
    test::writeFile(dir.file("not.png"), "this is not a png");
    const std::vector<BadImageCase> cases = {
        {"looks away", " --set camera.look_at=[0.0,3.2558,30.0]", "[camera]: sees nothing"},
        {"eye on target", " --set camera.eye=[0.0,0.0,0.0] --set camera.look_at=[0.0,0.0,0.0]", "camera.look_at"},
        {"fov", " --set camera.fov_degrees=180", "camera.fov_degrees"},
        {"odd size", " --set camera.width=640 --set target.fit=exact", "640"},
        {"bad fit", " --set target.fit=squash", "target.fit must be"},
        {"empty png", " --set target.image=\"" + dir.file("empty.png") + "\"", "empty.png"},
        {"not a png", " --set target.image=\"" + dir.file("not.png") + "\"", "not.png"},
        {"missing png", " --set target.image=\"" + dir.file("missing.png") + "\"", "missing.png"},
        {"image and volume", " --set target.fill=\"x.vdb\"", "cannot be combined"},
        {"bad projection", " --set camera.projection=fisheye", "camera.projection"},
    };
    for (const auto& c : cases) {
        const std::string out = dir.file(std::string("out-") + c.name);
        const auto r = runShapevo("run " + sourcePath("configs/tree-sketch.toml") + " --out '" + out + "'" + c.overrides);
        EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.name << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
    }
}

}  // namespace
}  // namespace shapevo
