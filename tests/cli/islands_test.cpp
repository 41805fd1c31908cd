// Islands end to end under mpirun: seeded 2-rank runs repeat byte for byte, a run resumed from
// its checkpoint equals the uninterrupted one, 4 ranks on 2 cores and async migration complete,
// an async island that finishes its generations first goes on until the slowest has and async
// islands at different generations resume, a different rank count on resume is refused, and
// SIGUSR1 checkpoints and exits 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <csignal>
#include <filesystem>
#include <sstream>
#include <thread>

#include "../island_compare.hpp"
#include "../test_support.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::curveWithoutTime;
using test::expectSameIslands;
using test::readFile;
using test::runShapevo;
using test::runShapevoMpi;
using test::sourcePath;
using test::spaceshipConfig;
using test::TempDir;

/// The generation of each island (rank order) in the newest checkpoint of run folder `run`.
std::vector<unsigned> asyncIslandGenerations(const std::string& run) {
    const std::vector<std::string> checkpoints = listCheckpoints(run);
    if (checkpoints.empty()) return {};
    const Grammar g = loadGrammar(sourcePath("grammars/spaceship.grammar"));
    const TreeFamily family(g);
    std::vector<unsigned> out;
    for (int r = 0; std::filesystem::exists(checkpoints.front() + "/" + islandFileName(r)); ++r)
        out.push_back(readIslandFile(checkpoints.front() + "/" + islandFileName(r), family, GenomeLimits{100}).generation);
    return out;
}

const std::string kSmallIslands = " --set ga.population=30 --set ga.elitism=4 --set ga.tournament=5 --set migration.interval=3"
                           " --set migration.count=3 --set checkpoint.interval=10 --set checkpoint.keep=10 -q";



TEST(Islands, SeededTwoRankRunRepeatsByteForByte) {
    TempDir dir;
    for (const char* run : {"a", "b"}) {
        const auto r = runShapevoMpi(2, "run " + spaceshipConfig() + " --seed 5 --set ga.generations=12 --out " + dir.file(run) + kSmallIslands);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("a/curve.csv"))), curveWithoutTime(readFile(dir.file("b/curve.csv"))));
    EXPECT_EQ(readFile(dir.file("a/best.genome")), readFile(dir.file("b/best.genome")));
    expectSameIslands(dir.file("a/checkpoint-000012"), dir.file("b/checkpoint-000012"), 2);
    EXPECT_NE(readFile(dir.file("a/summary.json")).find("\"islands\": 2"), std::string::npos);
}

TEST(Islands, ResumedRunEqualsTheUninterruptedOne) {
    test::LeakCheckedRanks leaks;  // this MPI path runs under LeakSanitizer too
    TempDir dir;
    auto whole = runShapevoMpi(2, "run " + spaceshipConfig() + " --seed 9 --set ga.generations=40 --out " + dir.file("whole") + kSmallIslands);
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    auto half = runShapevoMpi(2, "run " + spaceshipConfig() + " --seed 9 --set ga.generations=20 --out " + dir.file("half") + kSmallIslands);
    ASSERT_EQ(half.exitCode, 0) << half.output;
    auto rest = runShapevoMpi(2, "resume " + dir.file("half") + " --generations 40 -q");
    ASSERT_EQ(rest.exitCode, 0) << rest.output;
    expectSameIslands(dir.file("whole/checkpoint-000040"), dir.file("half/checkpoint-000040"), 2);
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("half/best.genome")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("whole/curve.csv"))), curveWithoutTime(readFile(dir.file("half/curve.csv"))));
}

TEST(Islands, FourRanksOnTwoCoresComplete) {
    TempDir dir;
    const auto r = runShapevoMpi(4, "run " + spaceshipConfig() + " --set ga.generations=6 --set run.threads=1 --out " + dir.file("r") + kSmallIslands);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("r/checkpoint-000006/island-0003.h5")));
}

TEST(Islands, AsyncMigrationCompletesUnderOversubscription) {
    TempDir dir;
    const auto r = runShapevoMpi(4, "run " + spaceshipConfig() + " --set ga.generations=15 --set migration.mode=async"
                                     " --set migration.interval=1 --set run.threads=1 --out " + dir.file("r") + kSmallIslands);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("r/summary.json")));
}

TEST(Islands, SyncRunsDoNotDependOnThreadsOrOnHowOftenTheIslandsMeet) {
    TempDir dir;
    const std::string base = "run " + spaceshipConfig() + " --seed 3 --set ga.generations=25" + kSmallIslands;
    ASSERT_EQ(runShapevoMpi(2, base + " --set run.threads=1 --out " + dir.file("a")).exitCode, 0);
    ASSERT_EQ(runShapevoMpi(2, base + " --set run.threads=2 --set migration.meeting_interval=1 --out " + dir.file("b")).exitCode, 0);
    ASSERT_EQ(runShapevoMpi(2, base + " --set migration.meeting_interval=7 --out " + dir.file("c")).exitCode, 0);
    const std::string curve = curveWithoutTime(readFile(dir.file("a/curve.csv")));
    EXPECT_EQ(std::count(curve.begin(), curve.end(), '\n'), 26);  // header + a row per generation
    for (const char* other : {"b", "c"}) {
        EXPECT_EQ(curve, curveWithoutTime(readFile(dir.file(std::string(other) + "/curve.csv")))) << other;
        EXPECT_EQ(readFile(dir.file("a/best.genome")), readFile(dir.file(std::string(other) + "/best.genome"))) << other;
    }
}

TEST(Islands, SummaryAndProgressLineGiveTheWaiting) {
    TempDir dir;
    const auto r = runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=30 --set run.threads=1 --out " + dir.file("r") +
                                        " --set ga.population=30 --set ga.elitism=4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("% (max "), std::string::npos) << r.output;
    const std::string summary = readFile(dir.file("r/summary.json"));
    for (const char* key : {"\"wait_share_max\": ", "\"wait_share_mean\": ", "\"wait_share_outside_checkpoints_max\": "}) {
        const auto at = summary.find(key);
        ASSERT_NE(at, std::string::npos) << key << summary;
        const double share = std::stod(summary.substr(at + std::strlen(key)));
        EXPECT_GE(share, 0.0) << key;
        EXPECT_LT(share, 1.0) << key;
    }
}

TEST(Islands, AsyncRunShowsTheAgeOfItsFiguresCheckpointsAndResumes) {
    test::LeakCheckedRanks leaks;  // this MPI path runs under LeakSanitizer too
    TempDir dir;
    const auto r = runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=40 --set migration.mode=async"
                                     " --set run.threads=1 --set checkpoint.interval=10 --out " + dir.file("r") +
                                     " --set ga.population=30 --set ga.elitism=4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("islands, oldest figures "), std::string::npos) << r.output;
    // the run ends once every island has done its 40 generations; the islands that got there
    // first went on, so the last checkpoint (named after rank 0's generation) may be past 40
    const std::vector<unsigned> first = asyncIslandGenerations(dir.file("r"));
    ASSERT_EQ(first.size(), 2u);
    for (unsigned g : first) EXPECT_GE(g, 40u);
    // islands at different generations resume together
    const auto more = runShapevoMpi(2, "resume " + dir.file("r") + " --generations 60 -q");
    ASSERT_EQ(more.exitCode, 0) << more.output;
    const std::vector<unsigned> second = asyncIslandGenerations(dir.file("r"));
    ASSERT_EQ(second.size(), 2u);
    for (unsigned g : second) EXPECT_GE(g, 60u);
    EXPECT_NE(readFile(dir.file("r/summary.json")).find("\"generations\": " + std::to_string(second[0])), std::string::npos);
    const auto inspect = runShapevo("inspect " + dir.file("r"));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("generation   " + std::to_string(second[0])), std::string::npos) << inspect.output;
}

TEST(Islands, AsyncIslandThatFinishesFirstGoesOnUntilTheSlowestHasDoneItsGenerations) {
    // Which island finishes first depends on the scheduler; both finish in the same microseconds
    // (and so stop together at the budget) only rarely, so up to three runs are given a chance.
    TempDir dir;
    bool wentOn = false;
    for (int attempt = 0; attempt < 3 && !wentOn; ++attempt) {
        const std::string out = dir.file("r" + std::to_string(attempt));
        const auto r = runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=30 --set migration.mode=async"
                                         " --set run.threads=1 --out " + out + " --set ga.population=30 --set ga.elitism=4 -q");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const std::vector<unsigned> generations = asyncIslandGenerations(out);
        ASSERT_EQ(generations.size(), 2u);
        for (unsigned g : generations) EXPECT_GE(g, 30u);
        wentOn = *std::max_element(generations.begin(), generations.end()) > 30;
    }
    EXPECT_TRUE(wentOn) << "no island went on evolving past the budget while the other finished";
}

TEST(Islands, ResumingWithAnotherRankCountNamesBothCounts) {
    TempDir dir;
    ASSERT_EQ(runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=3 --out " + dir.file("r") + kSmallIslands).exitCode, 0);
    const auto r = runShapevo("resume " + dir.file("r") + " --generations 6");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("holds 2 island(s) but 1 rank(s) were started"), std::string::npos) << r.output;
}

TEST(Islands, DamagedNewestCheckpointIsNamedAndThePreviousOneIsUsed) {
    test::LeakCheckedRanks leaks;  // this MPI path runs under LeakSanitizer too
    TempDir dir;
    ASSERT_EQ(runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=20 --out " + dir.file("r") + kSmallIslands).exitCode, 0);
    // truncate one island file of the newest checkpoint (20); 10 must be used instead
    const std::string victim = dir.file("r/checkpoint-000020/island-0001.h5");
    std::filesystem::resize_file(victim, std::filesystem::file_size(victim) / 2);
    const auto r = runShapevoMpi(2, "resume " + dir.file("r") + " --generations 22");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("checkpoint-000020 is incomplete or damaged"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("island-0001.h5"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("from " + dir.file("r/checkpoint-000010") + " (generation 10)"), std::string::npos) << r.output;
}

TEST(Islands, ExportWritesTheBestModelOfAnyCheckpoint) {
    TempDir dir;
    ASSERT_EQ(runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=10 --out " + dir.file("r") + kSmallIslands).exitCode, 0);
    const auto fromRun = runShapevo("export " + dir.file("r") + " --best -o " + dir.file("a.obj"));
    ASSERT_EQ(fromRun.exitCode, 0) << fromRun.output;
    // the newest checkpoint's best is the run's best: same mesh as best.obj
    EXPECT_EQ(readFile(dir.file("a.obj")), readFile(dir.file("r/best.obj")));
    const auto fromCheckpoint = runShapevo("export " + dir.file("r/checkpoint-000010") + " --best -o " + dir.file("b.ply"));
    ASSERT_EQ(fromCheckpoint.exitCode, 0) << fromCheckpoint.output;
    const auto inspect = runShapevo("inspect " + dir.file("r/checkpoint-000010"));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("islands      2"), std::string::npos) << inspect.output;
    const auto again = runShapevo("export " + dir.file("r") + " --best -o " + dir.file("a.obj"));
    EXPECT_EQ(again.exitCode, 2) << "an existing output is never overwritten";
}

TEST(Islands, TargetFitnessAndWallTimeStopEveryRankTogether) {
    TempDir dir;
    const auto target = runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=100000 --set run.target_fitness=0.95"
                                             " --out " + dir.file("t") + " --set ga.population=30 --set ga.elitism=4");
    ASSERT_EQ(target.exitCode, 0) << target.output;
    EXPECT_NE(target.output.find("done after reaching the target fitness"), std::string::npos) << target.output;
    const auto wall = runShapevoMpi(2, "run " + spaceshipConfig() + " --set ga.generations=100000000 --set run.wall_time=0.5"
                                           " --out " + dir.file("w") + " --set ga.population=30 --set ga.elitism=4 -q");
    ASSERT_EQ(wall.exitCode, 0) << wall.output;
    // it stopped long before the limit, with a checkpoint of the generation it stopped at
    const std::string summary = readFile(dir.file("w/summary.json"));
    const auto at = summary.find("\"generations\": ");
    ASSERT_NE(at, std::string::npos);
    const unsigned long generations = std::stoul(summary.substr(at + 15));
    EXPECT_LT(generations, 100000000ul);
    EXPECT_TRUE(std::filesystem::exists(dir.file("w/") + checkpointName(std::uint32_t(generations)))) << summary;
}

TEST(Islands, OtherCommandsRefuseSeveralRanks) {
    TempDir dir;
    const auto r = runShapevoMpi(2, "sample " + sourcePath("grammars/spaceship.grammar") + " -o " + dir.file("s.obj"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("only 'run' and 'resume' use several MPI ranks"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace shapevo
