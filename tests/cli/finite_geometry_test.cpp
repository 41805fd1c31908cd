// Geometry is finite or refused, end to end (issue 11 rows 5 and 6): a grammar whose models are
// sometimes non-finite evolves, counts them and writes only finite vertices; one whose models
// are never finite is refused at the start naming the rule; the primitive limit is a config key
// and reaching it is reported, never silent.
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

const std::string kSmallFinite = " --set ga.population=30 --set ga.elitism=4 --set ga.tournament=5 --set ga.generations=8 -q";

/// A config for `grammar` (written next to it) with the spaceship's target.
std::string configFor(const TempDir& dir, const std::string& grammar) { return test::configWithGrammar(dir, grammar); }

TEST(FiniteGeometry, SometimesNonFiniteModelsEvolveAreCountedAndNeverExported) {
    TempDir dir;
    const std::string cfg = configFor(dir, "start A\nrule A {\n  size (1, 0.5, 1.5)\n  box\n  child B prob 0.3\n  child C prob 0.7\n}\n"
                                           "rule C {\n  translate (0, 0, 1)\n  box\n  child C prob 0.5\n}\n"
                                           "rule B {\n  param p = uniform(0, 1)\n  scale (1 / (p * 0), sqrt(-1 - p * p), 1 / 0)\n  box\n}\n");
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmallFinite);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string summary = readFile(dir.file("run/summary.json"));
    EXPECT_EQ(summary.find("\"non_finite_models\": 0,"), std::string::npos) << summary;
    EXPECT_NE(r.output.find("non-finite"), std::string::npos) << r.output;
    const std::string obj = readFile(dir.file("run/best.obj"));
    EXPECT_EQ(obj.find("nan"), std::string::npos);
    EXPECT_EQ(obj.find("inf"), std::string::npos);
}

TEST(FiniteGeometry, AGrammarThatIsNeverFiniteIsRefusedAtTheStartNamingTheRule) {
    TempDir dir;
    const std::string cfg = configFor(dir, "start A\nrule A {\n  child B\n}\nrule B {\n  scale (1e30, 1, 1)\n  box\n}\n");
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmallFinite);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("rule B"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("non-finite"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("run"))) << "nothing is created";
}

TEST(FiniteGeometry, ReachingThePrimitiveLimitIsReportedNeverSilent) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("run") + kSmallFinite +
                              " --set genome.max_primitives=3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string summary = readFile(dir.file("run/summary.json"));
    EXPECT_EQ(summary.find("\"truncated_models\": 0,"), std::string::npos) << summary;
    EXPECT_NE(r.output.find("reached genome.max_primitives = 3"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace shapevo
