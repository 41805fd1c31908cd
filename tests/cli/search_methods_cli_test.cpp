// The search-method switch end to end: `search.method` = smc / sosmc / rjmcmc runs on two MPI
// islands, writes the usual outputs and checkpoints, and a run resumed from its checkpoint equals
// the uninterrupted one; a bad method name or [search] key is an input error (exit 2).
#include <gtest/gtest.h>

#include <filesystem>

#include "../island_compare.hpp"
#include "search/search_methods.hpp"
#include "../test_support.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::curveWithoutTime;
using test::expectSameIslands;
using test::readFile;
using test::spaceshipConfig;
using test::runShapevo;
using test::runShapevoMpi;
using test::sourcePath;
using test::TempDir;

const std::string kSmallMethods = " --set ga.population=24 --set ga.elitism=4 --set ga.tournament=5 --set migration.interval=3"
                           " --set migration.count=3 --set checkpoint.interval=5 --set checkpoint.keep=10 -q";


class SearchMethodCli : public ::testing::TestWithParam<const char*> {};

TEST_P(SearchMethodCli, TwoIslandRunResumedFromItsCheckpointEqualsTheUninterruptedOne) {
    TempDir dir;
    const std::string method = std::string(" --set search.method=") + GetParam();
    const std::string extra = std::string(GetParam()) == "rjmcmc" ? " --set search.rjmcmc_delayed_rejection=true" : "";
    auto whole = runShapevoMpi(2, "run " + spaceshipConfig() + " --seed 4 --set ga.generations=14 --out " + dir.file("whole") + method +
                                      extra + kSmallMethods);
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    auto half = runShapevoMpi(2, "run " + spaceshipConfig() + " --seed 4 --set ga.generations=7 --out " + dir.file("half") + method +
                                     extra + kSmallMethods);
    ASSERT_EQ(half.exitCode, 0) << half.output;
    auto rest = runShapevoMpi(2, "resume " + dir.file("half") + " --generations 14 -q");
    ASSERT_EQ(rest.exitCode, 0) << rest.output;
    expectSameIslands(dir.file("whole/checkpoint-000014"), dir.file("half/checkpoint-000014"), 2);
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("half/best.genome")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("whole/curve.csv"))), curveWithoutTime(readFile(dir.file("half/curve.csv"))));
    EXPECT_TRUE(std::filesystem::exists(dir.file("whole/best.obj")));
}

/// Every method of the table (the default, "hybrid", is also covered by tests/cli/run_test.cpp).
std::vector<const char*> baselineMethods() {
    std::vector<const char*> names;
    for (const SearchMethodEntry& m : searchMethods())
        names.push_back(m.name.data());  // the table's names are literals: NUL-terminated
    return names;
}

INSTANTIATE_TEST_SUITE_P(Methods, SearchMethodCli, ::testing::ValuesIn(baselineMethods()),
                         [](const auto& info) { return std::string(info.param); });

TEST(SearchMethodCli, UnknownMethodOrKeyIsAnInputError) {
    TempDir dir;
    const auto bad = runShapevo("run " + spaceshipConfig() + " --set search.method=annealing --out " + dir.file("a") + " -q");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("search.method must be \"hybrid\", \"ga\", \"smc\", \"sosmc\", \"rjmcmc\" or \"random\", got \"annealing\""),
              std::string::npos) << bad.output;
    const auto key = runShapevo("run " + spaceshipConfig() + " --set search.rjmcmc_temprature=1 --out " + dir.file("b") + " -q");
    EXPECT_EQ(key.exitCode, 2) << key.output;
    EXPECT_NE(key.output.find("unknown key 'rjmcmc_temprature' in [search]"), std::string::npos) << key.output;
    const auto flag = runShapevo("run " + spaceshipConfig() + " --set search.rjmcmc_delayed_rejection=1 --out " + dir.file("c") + " -q");
    EXPECT_EQ(flag.exitCode, 2) << flag.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a")));
}

}  // namespace
}  // namespace shapevo
