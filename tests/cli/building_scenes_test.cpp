// The building language's scenes through the command line: a config's [grammar.attr] and
// `--set grammar.attr.NAME=V` reach the grammar, are kept by resume (a resumed street equals the
// uninterrupted one), a misspelled attr is refused naming it (exit 2), and the castle scene runs
// and writes a coloured best.obj with its best.mtl.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

const std::string kSmallBuildings = " --set ga.population=20 --set ga.elitism=2 -q";

TEST(BuildingScenes, ResumedStreetWithAttrOverridesEqualsTheUninterruptedOne) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/street-whale.toml");
    const std::string attr = " --set grammar.attr.scale=0.25";
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("whole") + " --set ga.generations=6" + attr + kSmallBuildings).exitCode, 0);
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("split") + " --set ga.generations=3" + attr + kSmallBuildings).exitCode, 0);
    const auto r = runShapevo("resume " + dir.file("split") + " --generations 6 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("split/best.genome")));
    EXPECT_NE(readFile(dir.file("split/config.toml")).find("scale = 0.25"), std::string::npos);
    // the override changed the model: without it the best street differs
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("plain") + " --set ga.generations=6" + kSmallBuildings).exitCode, 0);
    EXPECT_NE(readFile(dir.file("whole/best.obj")), readFile(dir.file("plain/best.obj")));
}

TEST(BuildingScenes, AnAttrTheGrammarDoesNotDefineIsRefusedByName) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/street-whale.toml") + " --out " + dir.file("a") +
                              " --set grammar.attr.sclae=2" + kSmallBuildings);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("grammar.attr.sclae is set, but the grammar defines no attr 'sclae'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a")));
}

TEST(BuildingScenes, CastleRunWritesAColouredModelWithItsMaterials) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/castle-volume.toml") + " --out " + dir.file("c") +
                              " --set ga.generations=3 --set run.wall_time=0" + kSmallBuildings);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string obj = readFile(dir.file("c/best.obj"));
    EXPECT_NE(obj.find("mtllib best.mtl"), std::string::npos);
    EXPECT_NE(readFile(dir.file("c/best.mtl")).find("Kd "), std::string::npos);
    EXPECT_NE(readFile(dir.file("c/summary.json")).find("\"voxel_iou\""), std::string::npos);
}

}  // namespace
}  // namespace shapevo
