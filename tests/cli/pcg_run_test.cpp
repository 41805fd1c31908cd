// Runs of a `.pcg` graph file (configs/pcg-tree-volume.toml: grammars/pcg/tree.pcg toward the
// papers' tree volume) through every command a `.grammar` run has: the run folder's model, curve
// and genome; evaluate gives exactly the run's score; export, render and inspect take the run; a
// run stopped and resumed equals the uninterrupted one (curve and best genome byte for byte); two
// ranks with migration repeat byte for byte; an included subgraph file that changed since the run
// started stops a resume by name (exit 2), as a changed `.rule` include does.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace pcg_run_test {

using shapevo::test::curveWithoutTime;
using shapevo::test::evaluatedValue;
using shapevo::test::readFile;
using shapevo::test::runShapevo;
using shapevo::test::sourcePath;
using shapevo::test::summaryValue;
using shapevo::test::TempDir;
using shapevo::test::writeFile;

const std::string kPcgConfig = sourcePath("configs/pcg-tree-volume.toml");
const std::string kSmallPcg = " --set run.wall_time=0 --set ga.population=16 --set ga.elitism=4 --set ga.tournament=4 --threads 1 -q";

TEST(PcgRun, ARunWritesItsModelAndEvaluateExportRenderAndInspectTakeIt) {
    TempDir dir;
    const auto run = runShapevo("run " + kPcgConfig + " --out " + dir.file("run") + kSmallPcg + " --set ga.generations=3");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (const char* f : {"best.obj", "best.png", "best.genome", "curve.csv", "summary.json", "tree.pcg"})
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("run/") + f))) << f;
    const std::string summary = readFile(dir.file("run/summary.json"));
    const auto e = runShapevo("evaluate " + kPcgConfig + " " + dir.file("run/best.genome"));
    ASSERT_EQ(e.exitCode, 0) << e.output;
    EXPECT_EQ(evaluatedValue(e.output, "voxel_iou"), summaryValue(summary, "voxel_iou")) << e.output << summary;
    EXPECT_EQ(evaluatedValue(e.output, "fitness"), summaryValue(summary, "best_fitness")) << e.output << summary;
    EXPECT_EQ(evaluatedValue(e.output, "genes"), summaryValue(summary, "best_genes")) << e.output << summary;
    EXPECT_EQ(evaluatedValue(e.output, "primitives"), summaryValue(summary, "best_primitives")) << e.output << summary;

    const auto glb = runShapevo("export " + dir.file("run") + " --best -o " + dir.file("best.glb"));
    ASSERT_EQ(glb.exitCode, 0) << glb.output;
    EXPECT_GT(std::filesystem::file_size(dir.file("best.glb")), 100u);
    const auto obj = runShapevo("export " + dir.file("run") + " --best -o " + dir.file("best.obj"));
    ASSERT_EQ(obj.exitCode, 0) << obj.output;
    EXPECT_NE(readFile(dir.file("best.obj")).find("\nf "), std::string::npos);
    const auto render = runShapevo("render " + dir.file("run") + " -o " + dir.file("again.png"));
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_EQ(readFile(dir.file("again.png")), readFile(dir.file("run/best.png"))) << "render draws the run's best model";
    const auto inspect = runShapevo("inspect " + dir.file("run"));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("tree.pcg"), std::string::npos) << inspect.output;
    const auto translate = runShapevo("translate " + sourcePath("grammars/pcg/tree.pcg"));
    ASSERT_EQ(translate.exitCode, 0) << translate.output;
    EXPECT_NE(translate.output.find("start Tree"), std::string::npos) << translate.output;
}

// Slow under the sanitizers: run once, in the Release pass.
TEST(PcgRunSlow, AStoppedAndResumedRunEqualsTheUninterruptedOne) {
    TempDir dir;
    const auto whole = runShapevo("run " + kPcgConfig + " --out " + dir.file("whole") + kSmallPcg + " --set ga.generations=8");
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    const auto part = runShapevo("run " + kPcgConfig + " --out " + dir.file("part") + kSmallPcg + " --set ga.generations=4");
    ASSERT_EQ(part.exitCode, 0) << part.output;
    const auto resumed = runShapevo("resume " + dir.file("part") + " --generations 8 -q");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_EQ(readFile(dir.file("part/best.genome")), readFile(dir.file("whole/best.genome")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("part/curve.csv"))), curveWithoutTime(readFile(dir.file("whole/curve.csv"))));
    EXPECT_GT(curveWithoutTime(readFile(dir.file("whole/curve.csv"))).size(), 100u);
}

// Slow under the sanitizers: run once, in the Release pass.
TEST(PcgRunSlow, ASeededTwoRankRunWithMigrationRepeatsByteForByte) {
    TempDir dir;
    const std::string args = " --set ga.generations=6 --set migration.interval=2" + kSmallPcg;
    const auto a = shapevo::test::runShapevoMpi(2, "run " + kPcgConfig + " --out " + dir.file("a") + args);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const auto b = shapevo::test::runShapevoMpi(2, "run " + kPcgConfig + " --out " + dir.file("b") + args);
    ASSERT_EQ(b.exitCode, 0) << b.output;
    EXPECT_NE(readFile(dir.file("a/summary.json")).find("\"islands\": 2"), std::string::npos) << readFile(dir.file("a/summary.json"));
    EXPECT_EQ(readFile(dir.file("a/best.genome")), readFile(dir.file("b/best.genome")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("a/curve.csv"))), curveWithoutTime(readFile(dir.file("b/curve.csv"))));
}

/// A graph that uses `branch.pcg` as a node, and a config running it toward the tree volume.
std::string configWithSubgraph(const TempDir& dir) {
    writeFile(dir.file("branch.pcg"),
              "graph Branch\nparam reach = uniform(0.5, 2)\nin start : volume\nout end : volume\n"
              "node grow = size(0.3, reach, 0.3)\nnode wood = box()\nstart -> grow\ngrow -> wood\nwood -> end\n");
    writeFile(dir.file("main.pcg"),
              "graph Main\nin ground : volume\nnode trunk = size(0.5, 2, 0.5)\nnode arm = include \"branch.pcg\"()\n"
              "ground -> trunk\ntrunk -> arm.start\n");
    std::string cfg = readFile(kPcgConfig);
    auto replace = [&cfg](const std::string& from, const std::string& to) {
        const auto at = cfg.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        cfg.replace(at, from.size(), to);
    };
    replace("\"../grammars/pcg/tree.pcg\"", "\"main.pcg\"");
    replace("\"../targets/tree-volume.vdb\"", "\"" + sourcePath("targets/tree-volume.vdb") + "\"");
    writeFile(dir.file("main.toml"), cfg);
    return dir.file("main.toml");
}

TEST(PcgRun, AnIncludedGraphFileThatChangedStopsAResumeByName) {
    TempDir dir;
    const std::string cfg = configWithSubgraph(dir);
    auto r = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmallPcg + " --set ga.generations=2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("resume " + dir.file("run") + " --generations 3 -q");
    ASSERT_EQ(r.exitCode, 0) << "an unchanged include resumes\n" << r.output;

    writeFile(dir.file("branch.pcg"), readFile(dir.file("branch.pcg")) + "# changed\n");
    const std::string before = readFile(dir.file("run/curve.csv"));
    r = runShapevo("resume " + dir.file("run") + " --generations 4 -q");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("include"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("branch.pcg changed"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(dir.file("run/curve.csv")), before) << "nothing already written is lost";
}

}  // namespace pcg_run_test
