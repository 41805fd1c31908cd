// Resources a run asks for (issue 11, must-work 7 and row 14): a population the machine cannot
// hold is refused before anything is created, with the estimate; more threads than the machine
// gives are clamped with a warning on stderr, and the run records the number it used.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runCommand;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

TEST(ResourceLimits, APopulationTheMachineCannotHoldIsRefusedUpFrontWithTheEstimate) {
    TempDir dir;
    // 10^7 chromosomes of up to 10^7 genes: petabytes, more than any machine has
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("out") +
                              " --set ga.population=1e7 --set genome.max_genes=10000000 --set ga.elitism=2 -q");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + sourcePath("configs/spaceship.toml") +
                            ":ga.population: ga.population = 10000000 with genome.max_genes = 10000000 may need "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("population 10000000 x 5 copies x ("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("GiB this process may use"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("bad_alloc"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
}

TEST(ResourceLimits, MoreThreadsThanTheMachineGivesAreClampedWithAWarningOnStderr) {
    TempDir dir;
    const std::string stderrFile = dir.file("stderr.txt");
    const auto r = runCommand("{ " + std::string(SHAPEVO_BIN) + " run " + sourcePath("configs/spaceship.toml") + " --out " +
                              dir.file("r") + " --set run.threads=4096 --set ga.population=10 --set ga.generations=2" +
                              " --set ga.elitism=2 --set ga.tournament=3 2>" + stderrFile + "; }");
    ASSERT_EQ(r.exitCode, 0) << r.output << readFile(stderrFile);
    const std::string err = readFile(stderrFile);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(err, m, std::regex("shapevo: warning: run.threads = 4096 is more than the ([0-9]+) hardware "
                                                     "thread\\(s\\) this process may use; using ([0-9]+)")))
        << err;
    EXPECT_EQ(m[1], m[2]);
    const std::string used = m[1];
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << "stdout: " << r.output;
    EXPECT_NE(r.output.find("1 island(s) x " + used + " thread(s)"), std::string::npos) << r.output;
    EXPECT_NE(readFile(dir.file("r/summary.json")).find("\"threads\": " + used + "\n"), std::string::npos)
        << readFile(dir.file("r/summary.json"));
}

}  // namespace
}  // namespace shapevo
