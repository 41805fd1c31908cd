// Runs of a 2D graph grammar (the graph-derivation model family, issue 42) through every command
// a tree grammar's run has: the run folder's drawing, overlay, curve and genome; evaluate agrees
// with summary.json; export svg / png, render and inspect take the run; a run stopped and resumed
// equals the uninterrupted one; two ranks with migration repeat byte for byte; a genome drawn as
// a target is reached exactly; search methods that need a tree, volume targets and the new
// commands' bad inputs are refused with a located message and exit 2.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace graph_run_test {

using shapevo::test::evaluatedValue;
using shapevo::test::readFile;
using shapevo::test::summaryValue;
using shapevo::test::runShapevo;
using shapevo::test::sourcePath;
using shapevo::test::TempDir;

const std::string kConfig = sourcePath("configs/graph-tree-sketch.toml");
const std::string kSmall = " --set run.wall_time=0 --set ga.population=16 --set ga.elitism=4 --threads 1 -q";

TEST(GraphRun, WritesItsDrawingOverlayCurveAndGenomeAndEvaluateAgrees) {
    TempDir dir;
    const auto run = runShapevo("run " + kConfig + " --out " + dir.file("run") + kSmall + " --set ga.generations=3");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (const char* f : {"best.svg", "best.png", "best-overlay.png", "best.genome", "curve.csv", "summary.json", "tree.yml"})
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("run/") + f))) << f;
    EXPECT_NE(readFile(dir.file("run/best.svg")).find("<svg"), std::string::npos);
    const std::string summary = readFile(dir.file("run/summary.json"));
    const auto e = runShapevo("evaluate " + kConfig + " " + dir.file("run/best.genome"));
    ASSERT_EQ(e.exitCode, 0) << e.output;
    EXPECT_EQ(evaluatedValue(e.output, "fitness"), summaryValue(summary, "best_fitness")) << e.output << summary;
    EXPECT_EQ(evaluatedValue(e.output, "silhouette_iou"), summaryValue(summary, "silhouette_iou")) << e.output << summary;
    EXPECT_EQ(evaluatedValue(e.output, "primitives"), summaryValue(summary, "best_primitives")) << e.output << summary;

    const auto svg = runShapevo("export " + dir.file("run") + " --best --format svg -o " + dir.file("best.svg"));
    ASSERT_EQ(svg.exitCode, 0) << svg.output;
    EXPECT_EQ(readFile(dir.file("best.svg")), readFile(dir.file("run/best.svg")));
    const auto png = runShapevo("export " + dir.file("run") + " --best --format png -o " + dir.file("best.png"));
    ASSERT_EQ(png.exitCode, 0) << png.output;
    EXPECT_EQ(runShapevo("export " + dir.file("run") + " --best --format png -o " + dir.file("best.png")).exitCode, 2)
        << "an existing file is never replaced";
    const auto render = runShapevo("render " + dir.file("run") + " -o " + dir.file("render.png") + " --size 200x150");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find("200x150 drawing of"), std::string::npos) << render.output;
    const auto inspect = runShapevo("inspect " + dir.file("run"));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("productions; genome: graph derivation"), std::string::npos) << inspect.output;
}

// Slow under the sanitizers (16 s): run once, in the Release pass.
TEST(GraphRunSlow, AStoppedAndResumedRunEqualsTheUninterruptedOne) {
    TempDir dir;
    ASSERT_EQ(runShapevo("run " + kConfig + " --out " + dir.file("whole") + kSmall + " --set ga.generations=6").exitCode, 0);
    ASSERT_EQ(runShapevo("run " + kConfig + " --out " + dir.file("part") + kSmall + " --set ga.generations=3").exitCode, 0);
    const auto resumed = runShapevo("resume " + dir.file("part") + " --generations 6 -q");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_EQ(readFile(dir.file("part/best.genome")), readFile(dir.file("whole/best.genome")));
    EXPECT_EQ(shapevo::test::curveWithoutTime(readFile(dir.file("part/curve.csv"))),
              shapevo::test::curveWithoutTime(readFile(dir.file("whole/curve.csv"))));
}

// Slow under the sanitizers (17 s): run once, in the Release pass.
TEST(GraphRunSlow, ASeededTwoRankRunWithMigrationRepeatsByteForByte) {
    TempDir dir;
    const std::string args = " --set ga.generations=6 --set migration.interval=2" + kSmall;
    const auto a = shapevo::test::runShapevoMpi(2, "run " + kConfig + " --out " + dir.file("a") + args);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const auto b = shapevo::test::runShapevoMpi(2, "run " + kConfig + " --out " + dir.file("b") + args);
    ASSERT_EQ(b.exitCode, 0) << b.output;
    EXPECT_NE(readFile(dir.file("a/summary.json")).find("\"islands\": 2"), std::string::npos);
    EXPECT_EQ(readFile(dir.file("a/best.genome")), readFile(dir.file("b/best.genome")));
    EXPECT_EQ(shapevo::test::curveWithoutTime(readFile(dir.file("a/curve.csv"))),
              shapevo::test::curveWithoutTime(readFile(dir.file("b/curve.csv"))));
}

TEST(GraphRun, SearchMethodsThatNeedATreeAndVolumeTargetsAreRefused) {
    TempDir dir;
    for (const char* method : {"smc", "sosmc", "rjmcmc"}) {
        const auto r = runShapevo("run " + kConfig + " --out " + dir.file(method) + kSmall + " --set search.method=" + method);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("search.method"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("needs a derivation-tree grammar"), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir.file(method))) << "bad input leaves no run folder";
    }
    shapevo::test::writeFile(dir.file("volume.toml"), "[grammar]\nfile = \"" + sourcePath("grammars/graph/tree.yml") +
                                                          "\"\n[target]\nfill = \"" + sourcePath("targets/castle.vdb") + "\"\n");
    const auto v = runShapevo("run " + dir.file("volume.toml") + " --out " + dir.file("v") + kSmall);
    EXPECT_EQ(v.exitCode, 2) << v.output;
    EXPECT_NE(v.output.find("give it an image target"), std::string::npos) << v.output;
    EXPECT_NE(v.output.find("volume.toml"), std::string::npos) << v.output;
}

TEST(GraphRun, AGenomeDrawnAsATargetIsReachedExactlyByThatGenome) {
    TempDir dir;
    const auto sample = runShapevo("sample " + sourcePath("grammars/graph/facade.yml") + " --seed 11 --genome " + dir.file("f.genome") +
                                   " -o " + dir.file("f.svg"));
    ASSERT_EQ(sample.exitCode, 0) << sample.output;
    EXPECT_NE(sample.output.find("genome -> " + dir.file("f.genome")), std::string::npos) << sample.output;
    // the config's frame, with any picture: the target is drawn through it
    const auto target = runShapevo("target " + dir.file("f.genome") + " --image " + sourcePath("configs/graph-facade-reachable.toml") +
                                   " -o " + dir.file("t.png"));
    ASSERT_EQ(target.exitCode, 0) << target.output;
    const std::string config = readFile(sourcePath("configs/graph-facade-reachable.toml"));
    shapevo::test::writeFile(dir.file("c.toml"), "[grammar]\nfile = \"" + sourcePath("grammars/graph/facade.yml") + "\"\n[target]\nimage = \"" +
                                                     dir.file("t.png") + "\"\ncover = \"dark\"\n" + config.substr(config.find("[camera]")));
    const auto e = runShapevo("evaluate " + dir.file("c.toml") + " " + dir.file("f.genome"));
    ASSERT_EQ(e.exitCode, 0) << e.output;
    EXPECT_NE(e.output.find("silhouette_iou 1 "), std::string::npos) << e.output;
    EXPECT_EQ(runShapevo("target " + dir.file("f.genome") + " -o " + dir.file("u.png")).exitCode, 2) << "needs --image";
}

TEST(GraphRun, BadInputToTheNewCommandsIsALocatedErrorWithExit2) {
    TempDir dir;
    // a camera that does not look at the drawing from the front
    const auto side = runShapevo("run " + kConfig + " --out " + dir.file("side") + kSmall + " --set camera.eye=[5.0,7.27,10.0]");
    EXPECT_EQ(side.exitCode, 2) << side.output;
    EXPECT_NE(side.output.find("graph-tree-sketch.toml:[camera]: a 2D graph grammar's drawing is seen from the front"),
              std::string::npos) << side.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("side")));
    // target.tolerance on a tree grammar's silhouette
    const auto tree = runShapevo("run " + sourcePath("configs/tree-sketch.toml") + " --out " + dir.file("t") + kSmall +
                                 " --set target.tolerance=2");
    EXPECT_EQ(tree.exitCode, 2) << tree.output;
    EXPECT_NE(tree.output.find("[target] tolerance"), std::string::npos) << tree.output;
    // a genome of another grammar, for evaluate and target
    ASSERT_EQ(runShapevo("sample " + sourcePath("grammars/graph/mosaic.yml") + " --genome " + dir.file("m.genome") + " -o " +
                         dir.file("m.svg")).exitCode, 0);
    const auto other = runShapevo("evaluate " + kConfig + " " + dir.file("m.genome"));
    EXPECT_EQ(other.exitCode, 2) << other.output;
    EXPECT_NE(other.output.find(dir.file("m.genome")), std::string::npos) << other.output;
    const auto target = runShapevo("target " + dir.file("m.genome") + " --image " + kConfig + " -o " + dir.file("x.png"));
    EXPECT_EQ(target.exitCode, 2) << target.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    // sample --genome refuses an existing genome file before drawing anything
    const auto again = runShapevo("sample " + sourcePath("grammars/graph/mosaic.yml") + " --genome " + dir.file("m.genome") + " -o " +
                                  dir.file("n.svg"));
    EXPECT_EQ(again.exitCode, 2) << again.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("n.svg")));
}

}  // namespace graph_run_test
