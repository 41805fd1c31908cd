// End-to-end runs: the run folder holds every promised file, and a seeded run is repeatable
// byte for byte (best genome; curve except its wall-clock column) with 1 or 2 threads.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::curveWithoutTime;
using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

const std::string kSmallRun = " --set ga.population=40 --set ga.generations=8 --set ga.elitism=6 -q";


TEST(Run, WritesEveryOutputFile) {
    TempDir dir;
    // the paper's GA: its evaluation count is exact, 40 + 7 x (40 - 6)
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("run") + kSmallRun +
                              " --set search.method=ga");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"best.obj", "best.ply", "best.genome", "curve.csv", "summary.json", "config.toml", "spaceship.grammar"})
        EXPECT_TRUE(std::filesystem::exists(dir.file("run/") + f)) << f;
    const std::string summary = readFile(dir.file("run/summary.json"));
    for (const char* key : {"\"seed\"", "\"generations\": 8", "\"evaluations\": 278", "\"wall_seconds\"", "\"best_fitness\"", "\"voxel_iou\""})
        EXPECT_NE(summary.find(key), std::string::npos) << key << " in " << summary;
    const std::string curve = readFile(dir.file("run/curve.csv"));
    EXPECT_EQ(curve.rfind("generation,seconds,evaluations,best,mean,std,iou\n", 0), 0u);
    EXPECT_EQ(std::count(curve.begin(), curve.end(), '\n'), 9);
    // the last row's iou is the IoU of the model summary.json reports
    const std::string last = curve.substr(curve.rfind('\n', curve.size() - 2) + 1);
    const std::string iou = last.substr(last.rfind(',') + 1, last.size() - last.rfind(',') - 2);
    ASSERT_FALSE(iou.empty()) << last;
    EXPECT_NE(summary.find("\"voxel_iou\": " + iou + ","), std::string::npos) << iou << " in " << summary;
}

TEST(Run, ProgressLinePerGeneration) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("run") +
                              " --set ga.population=20 --set ga.generations=3 --set ga.elitism=2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* g : {"gen 1/3", "gen 2/3", "gen 3/3"}) EXPECT_NE(r.output.find(g), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("evals/s"), std::string::npos);
    EXPECT_NE(r.output.find("gen 3/3  best "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("  IoU "), std::string::npos) << "the best model's IoU next to its fitness: " << r.output;
    EXPECT_NE(r.output.find("ETA"), std::string::npos);
}

TEST(Determinism, SameSeedGivesIdenticalGenomeAndCurveWithOneOrTwoThreads) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/spaceship.toml");
    ASSERT_EQ(runShapevo("run " + cfg + " --seed 42 --threads 1 --out " + dir.file("a") + kSmallRun).exitCode, 0);
    ASSERT_EQ(runShapevo("run " + cfg + " --seed 42 --threads 2 --out " + dir.file("b") + kSmallRun).exitCode, 0);
    ASSERT_EQ(runShapevo("run " + cfg + " --seed 43 --threads 2 --out " + dir.file("c") + kSmallRun).exitCode, 0);
    EXPECT_EQ(readFile(dir.file("a/best.genome")), readFile(dir.file("b/best.genome")));
    EXPECT_EQ(readFile(dir.file("a/best.obj")), readFile(dir.file("b/best.obj")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("a/curve.csv"))), curveWithoutTime(readFile(dir.file("b/curve.csv"))));
    // and the seed matters
    EXPECT_NE(curveWithoutTime(readFile(dir.file("a/curve.csv"))), curveWithoutTime(readFile(dir.file("c/curve.csv"))));
}

TEST(Evaluate, ScoresTheReachableTargetsOwnDerivationNearTheOptimum) {
    const auto r = runShapevo("evaluate " + sourcePath("configs/spaceship.toml") + " " +
                              sourcePath("targets/spaceship-reachable.genome"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const double fitness = std::stod(r.output.substr(r.output.find("fitness ") + 8));
    EXPECT_GT(fitness, 0.99);
    EXPECT_LE(fitness, 1.0);
}

}  // namespace
}  // namespace shapevo
