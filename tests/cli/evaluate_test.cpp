// `shapevo evaluate` scores a run's best.genome through the run's own scene loading: for an image
// config and a volume config (with the run's --set overrides) it prints exactly the best fitness
// and IoU that the run wrote into summary.json.
#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::evaluatedValue;
using test::readFile;
using test::summaryValue;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

const std::string kSmallEvaluate = " --set ga.population=30 --set ga.generations=6 --set ga.elitism=6 -q";

/// Run `config` with `overrides`, evaluate its best.genome with `evalOverrides`, and compare.
void expectEvaluateMatchesRun(const std::string& config, const std::string& overrides, const std::string& iouKey,
                              const std::string& evalOverrides) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/" + config);
    const auto run = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmallEvaluate + overrides);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string summary = readFile(dir.file("run/summary.json"));
    const auto r = runShapevo("evaluate " + cfg + " " + dir.file("run/best.genome") + evalOverrides);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(evaluatedValue(r.output, "fitness"), summaryValue(summary, "best_fitness")) << r.output << summary;
    EXPECT_EQ(evaluatedValue(r.output, iouKey), summaryValue(summary, iouKey)) << r.output << summary;
    EXPECT_EQ(evaluatedValue(r.output, "genes"), summaryValue(summary, "best_genes")) << r.output << summary;
    EXPECT_EQ(evaluatedValue(r.output, "primitives"), summaryValue(summary, "best_primitives")) << r.output << summary;
}

TEST(Evaluate, ImageConfigGivesTheRunsBestFitness) {
    expectEvaluateMatchesRun("tree-sketch.toml", "", "silhouette_iou", "");
}

TEST(Evaluate, VolumeConfigGivesTheRunsBestFitness) {
    expectEvaluateMatchesRun("spaceship.toml", "", "voxel_iou", "");
}

TEST(Evaluate, SetOverridesScoreAsInTheRun) {
    const std::string weighted = " --set score.form=weighted --set score.empty_weight=-0.25";
    expectEvaluateMatchesRun("spaceship.toml", weighted, "voxel_iou", weighted);
    // and they matter: the same genome without them scores otherwise
    TempDir dir;
    const std::string cfg = sourcePath("configs/spaceship.toml");
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("run") + kSmallEvaluate + weighted).exitCode, 0);
    const auto plain = runShapevo("evaluate " + cfg + " " + dir.file("run/best.genome"));
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_NE(evaluatedValue(plain.output, "fitness"), summaryValue(readFile(dir.file("run/summary.json")), "best_fitness"));
}

TEST(Evaluate, ImageConfigWithAnotherGrammarsGenomeIsRefused) {
    const auto r = runShapevo("evaluate " + sourcePath("configs/tree-sketch.toml") + " " +
                              sourcePath("targets/spaceship-reachable.genome"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("spaceship-reachable.genome"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace shapevo
