// The run's limit (run/run_limit.hpp): a wall time alone runs for that time (no generation
// limit), a generation count alone for that many generations, both for whichever comes first,
// neither for the default count; the start-up line's text names it, and resume's new limits
// follow the same rules.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run/config_file.hpp"
#include "run/run_limit.hpp"

namespace shapevo {
namespace {

RunSettings runLimitParse(const std::string& extra, const std::vector<std::string>& overrides = {}) {
    return parseConfig("[grammar]\nfile = \"g.grammar\"\n[target]\nimage = \"logo.png\"\n" + extra, "/configs/x.toml", overrides);
}

TEST(RunLimit, AWallTimeAloneRunsForThatTime) {
    const RunSettings s = runLimitParse("", {"run.wall_time=60"});
    EXPECT_EQ(s.population.generations, kNoGenerationLimit);
    EXPECT_EQ(runLimitText(s), "limit: 60 s wall time");
    const RunSettings inFile = runLimitParse("[run]\nwall_time = 2.5\n[ga]\npopulation = 60\n");
    EXPECT_EQ(inFile.population.generations, kNoGenerationLimit);
    EXPECT_EQ(runLimitText(inFile), "limit: 2.5 s wall time");
}

TEST(RunLimit, AGenerationCountAloneOrNeitherRunsThatManyGenerations) {
    EXPECT_EQ(runLimitText(runLimitParse("")), "limit: 50 generations");
    EXPECT_EQ(runLimitParse("").population.generations, 50u);
    EXPECT_EQ(runLimitText(runLimitParse("[ga]\ngenerations = 7\n")), "limit: 7 generations");
    EXPECT_EQ(runLimitText(runLimitParse("[ga]\ngenerations = 1\n")), "limit: 1 generation");
    EXPECT_EQ(runLimitText(runLimitParse("[run]\nwall_time = 0\n")), "limit: 50 generations");  // 0: no wall time
}

TEST(RunLimit, BothGivenRunUntilWhicheverComesFirst) {
    const RunSettings s = runLimitParse("[run]\nwall_time = 60\n", {"ga.generations=50"});
    EXPECT_EQ(s.population.generations, 50u);
    EXPECT_EQ(runLimitText(s), "limit: 50 generations or 60 s, whichever comes first");
    EXPECT_EQ(runLimitText(runLimitParse("[run]\nwall_time = 60\n[ga]\ngenerations = 100000\n")),
              "limit: 100000 generations or 60 s, whichever comes first");
}

TEST(RunLimit, ResumesNewLimitsFollowTheSameRules) {
    // resume sets what it was given and settles again (run/run_job.cpp)
    RunSettings s = runLimitParse("");
    s.wallTime = 30;  // resume --wall-time 30 on a run without either: the wall time alone
    settleRunLimit(s);
    EXPECT_EQ(runLimitText(s), "limit: 30 s wall time");
    s.population.generations = 80, s.generationsGiven = true;  // and --generations 80
    settleRunLimit(s);
    EXPECT_EQ(runLimitText(s), "limit: 80 generations or 30 s, whichever comes first");
    RunSettings timed = runLimitParse("", {"run.wall_time=60"});
    timed.wallTime = 0;  // no wall time any more: the default count, not an endless run
    settleRunLimit(timed);
    EXPECT_EQ(timed.population.generations, 50u);
}

}  // namespace
}  // namespace shapevo
