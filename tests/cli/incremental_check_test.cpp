// Incremental scoring end to end: every shipped scene runs 100,000 children with
// score.check_incremental = true (each child scored both ways; the run stops on the first
// difference; the zoned city 20,000: each of its children is one gene of 1,024 blocks derived and
// voxelized whole, so 20,000 take as long as 100,000 of the next slowest scene), the baselines'
// moves too; a seeded run is byte-identical with the switch on and off;
// a cache that fills its score.cache_mb says so once and changes nothing; the [score] keys are
// checked like every other key (exit 2).
// The 100,000-children runs are labelled slow (the sanitizer pass skips them: tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "../test_support.hpp"
#include "graph/read_graph_grammar.hpp"
#include "run/config_file.hpp"

namespace shapevo {
namespace {

using test::curveWithoutTime;
using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

/// The "evaluations" figure of a run's summary.json.
std::uint64_t evaluationsOf(const std::string& runDir) {
    const std::string summary = readFile(runDir + "/summary.json");
    std::smatch m;
    if (!std::regex_search(summary, m, std::regex("\"evaluations\": ([0-9]+)"))) return 0;
    return std::stoull(m[1]);
}

/// The shipped configs of derivation-tree grammars: incremental scoring is the tree family's (a 2D
/// graph grammar's drawing is scored whole, score/image/drawing_scorer.hpp).
std::vector<std::string> shippedConfigs() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(sourcePath("configs")))
        if (e.path().extension() == ".toml" && !graph::isGraphGrammarPath(loadConfig(e.path().string()).grammarPath))
            names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class IncrementalCheckSlow : public ::testing::TestWithParam<std::string> {};

/// How many children a scene's check scores both ways.
std::uint64_t childrenToCheck(const std::string& scene) { return scene == "city-zones-volume" ? 20000 : 100000; }

TEST_P(IncrementalCheckSlow, EveryChildScoresTheSameBothWays) {
    TempDir dir;
    const std::string config = sourcePath("configs/" + GetParam() + ".toml");
    const RunSettings s = loadConfig(config);
    const std::uint64_t perGeneration = s.population.population - s.ga.elitism, children = childrenToCheck(GetParam());
    const std::uint64_t generations = (children + perGeneration - 1) / perGeneration;
    const auto r = runShapevo("run " + config + " --seed 2 --threads 2 -q --set score.check_incremental=true --set run.wall_time=0" +
                              " --set ga.generations=" + std::to_string(generations) + " --set checkpoint.interval=1000000" +
                              " --set checkpoint.seconds=0 --out " + dir.file("run"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GE(evaluationsOf(dir.file("run")), children);
}

INSTANTIATE_TEST_SUITE_P(Scenes, IncrementalCheckSlow, ::testing::ValuesIn(shippedConfigs()),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

TEST(IncrementalCheckSlow, TheBaselinesMovesScoreTheSameBothWays) {
    TempDir dir;
    for (const char* method : {"smc", "sosmc", "rjmcmc"})
        for (const char* scene : {"tree-logo", "spaceship-paper"}) {
            SCOPED_TRACE(std::string(method) + " " + scene);
            const std::string out = dir.file(std::string(method) + "-" + scene);
            const auto r = runShapevo("run " + sourcePath(std::string("configs/") + scene + ".toml") +
                                      " --seed 3 -q --set score.check_incremental=true --set run.wall_time=0 --set search.method=" +
                                      method + " --set ga.generations=300 --out " + out);
            ASSERT_EQ(r.exitCode, 0) << r.output;
            EXPECT_GE(evaluationsOf(out), 400u);  // SMC stops evaluating particles that completed
        }
}

TEST(IncrementalCheck, SeededRunsAreByteIdenticalWithTheSwitchOnAndOff) {
    TempDir dir;
    for (const char* scene : {"tree-logo", "spaceship"}) {
        SCOPED_TRACE(scene);
        std::string curve[2], best[2];
        for (int on = 0; on < 2; ++on) {
            const std::string out = dir.file(std::string(scene) + (on ? "-on" : "-off"));
            const auto r = runShapevo("run " + sourcePath(std::string("configs/") + scene + ".toml") +
                                      " --seed 5 -q --set run.wall_time=0 --set ga.generations=60 --set score.incremental=" +
                                      (on ? "true" : "false") + " --out " + out);
            ASSERT_EQ(r.exitCode, 0) << r.output;
            curve[on] = curveWithoutTime(readFile(out + "/curve.csv"));
            best[on] = readFile(out + "/best.genome");
        }
        EXPECT_EQ(curve[0], curve[1]);
        EXPECT_EQ(best[0], best[1]);
        EXPECT_GT(curve[0].size(), 1000u);
    }
}

TEST(IncrementalCheck, AFullCacheIsSaidOnceAndChangesNothing) {
    TempDir dir;
    std::string best[2], curve[2], output[2];
    const char* sizes[2] = {"1", "128"};  // tiny, and the default
    for (int i = 0; i < 2; ++i) {
        const std::string out = dir.file(std::string("mb") + sizes[i]);
        const auto r = runShapevo("run " + sourcePath("configs/tree-logo.toml") +
                                  " --seed 5 --set run.wall_time=0 --set ga.generations=40 --set score.cache_mb=" + sizes[i] +
                                  " --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        best[i] = readFile(out + "/best.genome");
        curve[i] = curveWithoutTime(readFile(out + "/curve.csv"));
        output[i] = r.output;
    }
    const std::string said = "incremental scoring has filled score.cache_mb = 1";
    const std::size_t at = output[0].find(said);
    ASSERT_NE(at, std::string::npos) << output[0];
    EXPECT_EQ(output[0].find(said, at + 1), std::string::npos) << "said more than once:\n" << output[0];
    EXPECT_EQ(output[1].find("incremental scoring has filled"), std::string::npos) << output[1];
    EXPECT_EQ(best[0], best[1]);
    EXPECT_EQ(curve[0], curve[1]);
}

TEST(IncrementalCheck, BadScoreKeysAreInputErrors) {
    TempDir dir;
    const std::string config = sourcePath("configs/spaceship.toml");
    const struct {
        const char* set;
        const char* message;
    } cases[] = {
        {"score.cache_mb=0", "score.cache_mb"},
        {"score.cache_mb=-3", "score.cache_mb"},
        {"score.incremental=1", "score.incremental"},
        {"score.check_incremental=\"yes\"", "score.check_incremental"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.set);
        const auto r = runShapevo("run " + config + " -q --set " + c.set + " --out " + dir.file("bad"));
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir.file("bad")));
    }
}

}  // namespace
}  // namespace shapevo
