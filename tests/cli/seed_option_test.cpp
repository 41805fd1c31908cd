// `run --seed`: the seed is an override written into the run's config text (config.toml and the
// checkpoints), so `resume` goes on with it; a seed outside what a config's run.seed can hold
// (0 .. 2^63-1) is an error naming --seed, never saturated or wrapped (issue 11, rows 8 and 14).
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"
#include "run/config_file.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

const std::string kSmallSeed = " --set ga.population=20 --set ga.generations=3 --set ga.elitism=2 -q";

TEST(SeedOption, IsWrittenIntoTheRunsConfigAndKeptByResume) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --seed 99 --out " + dir.file("a") + kSmallSeed);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string config = readFile(dir.file("a/config.toml"));
    EXPECT_EQ(parseConfig(config, dir.file("a/config.toml")).seed, 99u) << config;
    const auto resumed = runShapevo("resume " + dir.file("a") + " --generations 5 -q");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    const std::string summary = readFile(dir.file("a/summary.json"));
    EXPECT_NE(summary.find("\"seed\": 99,"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"generations\": 5"), std::string::npos) << summary;
}

TEST(SeedOption, TheLargestSeedAConfigHoldsIsKeptExactly) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --seed 9223372036854775807 --out " +
                              dir.file("a") + kSmallSeed);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(parseConfig(readFile(dir.file("a/config.toml")), "config.toml").seed, 9223372036854775807u);
    EXPECT_NE(readFile(dir.file("a/summary.json")).find("\"seed\": 9223372036854775807,"), std::string::npos);
}

TEST(SeedOption, BeyondWhatAConfigHoldsIsAnErrorNotSaturated) {
    TempDir dir;
    for (const std::string seed : {"18446744073709551616", "18446744073709551615", "9223372036854775808", "-1", "12abc"}) {
        const std::string out = dir.file("out-" + seed);
        const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --seed " + seed + " --out " + out + kSmallSeed);
        EXPECT_EQ(r.exitCode, 2) << seed << ": " << r.output;
        EXPECT_NE(r.output.find("shapevo: error: --seed: "), std::string::npos) << seed << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << seed;
    }
    // sample's seed is not written into a config: all of 0 .. 2^64-1, and no further
    const std::string grammar = sourcePath("grammars/spaceship.grammar");
    const auto over = runShapevo("sample " + grammar + " --seed 18446744073709551616 -o " + dir.file("over.obj"));
    EXPECT_EQ(over.exitCode, 2) << over.output;
    EXPECT_NE(over.output.find("--seed: 18446744073709551616 is out of range [0, 18446744073709551615]"), std::string::npos)
        << over.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("over.obj")));
    EXPECT_EQ(runShapevo("sample " + grammar + " --seed 18446744073709551615 -o " + dir.file("max.obj")).exitCode, 0);
}

}  // namespace
}  // namespace shapevo
