// A wall time means what it says (run/run_limit.hpp): a run given run.wall_time and no
// ga.generations runs until that time, past the default 50 generations; with both it stops at
// whichever comes first; the run's first line names the limit. A resumed wall-time run keeps its
// limit: complete once the time is spent, extended by resume --wall-time. Two ranks in sync mode
// stop together, with the checkpoint of the generation they stopped at.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../test_support.hpp"
#include "checkpoint/checkpoint_file.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

/// configs/spaceship.toml without its ga.generations (absolute paths) in `dir`; returns its path.
std::string wallTimeSpaceshipWithoutGenerations(const TempDir& dir) {
    std::string cfg = readFile(sourcePath("configs/spaceship.toml"));
    const auto at = cfg.find("generations = 50\n");
    EXPECT_NE(at, std::string::npos) << "configs/spaceship.toml changed";
    if (at != std::string::npos) cfg.erase(at, std::string("generations = 50\n").size());
    for (auto p = cfg.find("\"../"); p != std::string::npos; p = cfg.find("\"../", p)) cfg.replace(p, 4, "\"" + sourcePath(""));
    test::writeFile(dir.file("no-generations.toml"), cfg);
    return dir.file("no-generations.toml");
}

const std::string kWallTimeSmall = " --set ga.population=20 --set ga.elitism=4 --set ga.tournament=4 --threads 1";

unsigned long wallTimeGenerations(const std::string& folder) {
    const std::string summary = readFile(folder + "/summary.json");
    const auto at = summary.find("\"generations\": ");
    return at == std::string::npos ? 0 : std::stoul(summary.substr(at + 15));
}

std::string wallTimeFirstLine(const std::string& output) { return output.substr(0, output.find('\n')); }

TEST(WallTimeLimit, AWallTimeAloneRunsPastTheDefaultGenerationsUntilItIsSpent) {
    TempDir dir;
    const std::string cfg = wallTimeSpaceshipWithoutGenerations(dir);
    const auto r = runShapevo("run " + cfg + " --set run.wall_time=2 --out " + dir.file("w") + kWallTimeSmall);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string first = wallTimeFirstLine(r.output);
    EXPECT_NE(first.find("shapevo run spaceship: "), std::string::npos) << first;
    EXPECT_NE(first.find(", limit: 2 s wall time"), std::string::npos) << first;
    EXPECT_NE(r.output.find("the wall-time budget"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gen 1  best "), std::string::npos) << "no total without a generation limit: " << r.output;
    const unsigned long generations = wallTimeGenerations(dir.file("w"));
    EXPECT_GT(generations, 50ul) << "stopped at the default generation count, not at its wall time";
    EXPECT_TRUE(std::filesystem::exists(dir.file("w/") + checkpointName(std::uint32_t(generations))));
    const std::string summary = readFile(dir.file("w/summary.json"));
    const auto at = summary.find("\"wall_seconds\": ");
    ASSERT_NE(at, std::string::npos) << summary;
    EXPECT_GE(std::stod(summary.substr(at + 16)), 2.0);

    // resumed: complete, its time spent; --wall-time gives it more
    const auto again = runShapevo("resume " + dir.file("w"));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("is complete at generation " + std::to_string(generations) +
                                "; its wall time (2 s) is spent: pass --wall-time S to continue it"),
              std::string::npos)
        << again.output;
    EXPECT_EQ(wallTimeGenerations(dir.file("w")), generations);
    const auto more = runShapevo("resume " + dir.file("w") + " --wall-time 2.5");
    ASSERT_EQ(more.exitCode, 0) << more.output;
    EXPECT_NE(more.output.find("limit: 2.5 s wall time"), std::string::npos) << more.output;
    EXPECT_GT(wallTimeGenerations(dir.file("w")), generations);
}

TEST(WallTimeLimit, AGenerationCountAloneOrWithAWallTimeNamesItsLimit) {
    TempDir dir;
    const std::string cfg = wallTimeSpaceshipWithoutGenerations(dir);
    const auto both = runShapevo("run " + cfg + " --set run.wall_time=60 --set ga.generations=30 --out " + dir.file("b") + kWallTimeSmall);
    ASSERT_EQ(both.exitCode, 0) << both.output;
    EXPECT_NE(wallTimeFirstLine(both.output).find(", limit: 30 generations or 60 s, whichever comes first"), std::string::npos)
        << both.output;
    EXPECT_EQ(wallTimeGenerations(dir.file("b")), 30ul);  // the generations came first
    const auto neither = runShapevo("run " + cfg + " --out " + dir.file("n") + kWallTimeSmall);
    ASSERT_EQ(neither.exitCode, 0) << neither.output;
    EXPECT_NE(wallTimeFirstLine(neither.output).find(", limit: 50 generations"), std::string::npos) << neither.output;
    EXPECT_EQ(wallTimeGenerations(dir.file("n")), 50ul);
}

TEST(WallTimeLimit, TwoRanksInSyncModeStopTogetherAtTheirWallTime) {
    TempDir dir;
    const std::string cfg = wallTimeSpaceshipWithoutGenerations(dir);
    const auto r = test::runShapevoMpi(2, "run " + cfg + " --set run.wall_time=1.5 --out " + dir.file("m") + kWallTimeSmall);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("2 island(s) x 1 thread(s)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("limit: 1.5 s wall time\n"), std::string::npos) << r.output;
    const unsigned long generations = wallTimeGenerations(dir.file("m"));
    EXPECT_GT(generations, 50ul);
    // one checkpoint of both islands at the generation they stopped at
    EXPECT_TRUE(std::filesystem::exists(dir.file("m/") + checkpointName(std::uint32_t(generations)) + "/" + islandFileName(1)))
        << r.output;
}

}  // namespace
}  // namespace shapevo
