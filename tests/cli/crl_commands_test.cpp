// CastleMaker rule files through every command: a config's grammar.file may name a .rule file;
// run (with checkpoints), resume (equal to the uninterrupted run), export, evaluate, sample and
// translate take it (translate refuses a .grammar file); an include changed since the run started
// is caught on resume.
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

/// configs/castle-volume.toml with its target by absolute path and grammar.file = `rule`.
std::string castleConfig(const TempDir& dir, const std::string& rule) {
    std::string cfg = readFile(sourcePath("configs/castle-volume.toml"));
    auto replace = [&cfg](const std::string& from, const std::string& to) {
        const auto at = cfg.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        cfg.replace(at, from.size(), to);
    };
    replace("\"../grammars/castle.grammar\"", "\"" + rule + "\"");
    replace("\"../targets/castle.vdb\"", "\"" + sourcePath("targets/castle.vdb") + "\"");
    writeFile(dir.file("crl.toml"), cfg);
    return dir.file("crl.toml");
}

const std::string kSmallCrl = " --set ga.population=16 --set ga.elitism=2 --set run.wall_time=0 -q";

TEST(CrlCommands, ARuleFileRunsResumesExportsAndEvaluates) {
    TempDir dir;
    writeFile(dir.file("parts.rule"), "Keep -> extrude(rand(1, 8)) {Body};\nBody -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    writeFile(dir.file("castle.rule"),
              "include \"parts.rule\";\nLot = rect(-6, -6, 6, 6);\nLot -> center(rand(2, 10), rand(2, 10)) {Keep};\n"
              "Lot -> corners(0.2, 0.2, 1, 1, 1, 1) {Tower};\nTower -> extrude(rand(2, 9)) {T};\n"
              "T -> [0.5] insert_cylinder(1, 1, 1, 16), [0.5] insert_volume(1, 1, 1, 0, 0, 1);\n");
    const std::string cfg = castleConfig(dir, dir.file("castle.rule"));
    auto r = runShapevo("run " + cfg + " --out " + dir.file("whole") + " --set ga.generations=6" + kSmallCrl);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("run " + cfg + " --out " + dir.file("split") + " --set ga.generations=3" + kSmallCrl);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("resume " + dir.file("split") + " --generations 6 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("split/best.genome")));
    EXPECT_NE(readFile(dir.file("whole/summary.json")).find("\"voxel_iou\""), std::string::npos);

    r = runShapevo("export " + dir.file("whole") + " --best -o " + dir.file("best.glb"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(dir.file("best.glb")), 100u);
    r = runShapevo("evaluate " + cfg + " " + dir.file("whole/best.genome"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("iou"), std::string::npos) << r.output;

    r = runShapevo("sample " + dir.file("castle.rule") + " --seed 3 -o " + dir.file("s.obj") + " --genome " + dir.file("s.genome"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("evaluate " + cfg + " " + dir.file("s.genome"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("translate " + dir.file("castle.rule"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("rule Keep {"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("per piece"), std::string::npos) << r.output;

    // an include that changed since the run started stops a resume (as any input does)
    writeFile(dir.file("parts.rule"), "Keep -> extrude(rand(1, 9)) {Body};\nBody -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    r = runShapevo("resume " + dir.file("split") + " --generations 8 -q");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("include"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("parts.rule changed"), std::string::npos) << r.output;
}

TEST(CrlCommands, ABadRuleFileIsOneLocatedMessageAndExitTwo) {
    TempDir dir;
    writeFile(dir.file("bad.rule"), "L = rect(0, 0, 1, 1);\nL -> extrude(2) {Missing};\n");
    const auto r = runShapevo("sample " + dir.file("bad.rule") + " -o " + dir.file("x.obj"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("bad.rule:2:18: handle 'Missing' is never defined"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.obj")));
}

TEST(CrlCommands, TranslateRefusesAFileThatNeedsNoTranslation) {
    const std::string grammar = sourcePath("grammars/castle.grammar");
    const auto r = runShapevo("translate " + grammar);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find(grammar + ": is read as a shapevo grammar, which needs no translation; shapevo translate reads a "
                                      "CastleMaker rule file (.rule)"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace shapevo
