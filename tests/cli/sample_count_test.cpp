// shapevo sample end to end: --count N writes N numbered variations (out-001.obj, ...) whose
// seeds follow --seed, refuses every existing output before writing any, and bad counts or a
// size window no derivation meets are exit 2 with nothing written. A slot's prob is followed
// through the binary too (the old sample expressed no optional child with --min-genes 1).
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

const char* kSampleCountAB = "start S\nrule S { box child A prob 0.05 child B prob 0.95 }\nrule A { box }\nrule B { box }\n";

std::size_t countOf(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(SampleCount, WritesNumberedFilesWithSeedsFollowingTheSeed) {
    TempDir dir;
    writeFile(dir.file("ab.grammar"), kSampleCountAB);
    const auto r = runShapevo("sample " + dir.file("ab.grammar") + " --seed 5 --count 3 -o " + dir.file("m.obj") +
                              " --genome " + dir.file("g.genome"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(countOf(r.output, "\n"), 3u) << "one line per file: " << r.output;
    for (int k = 1; k <= 3; ++k) {
        const std::string n = "00" + std::to_string(k);
        EXPECT_TRUE(fs::exists(dir.file("m-" + n + ".obj"))) << n;
        EXPECT_TRUE(fs::exists(dir.file("g-" + n + ".genome"))) << n;
        EXPECT_NE(r.output.find("(seed " + std::to_string(4 + k) + ") -> " + dir.file("m-" + n + ".obj") + ", " +
                                dir.file("g-" + n + ".genome") + "\n"),
                  std::string::npos)
            << r.output;
    }
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
    EXPECT_FALSE(fs::exists(dir.file("g.genome")));

    // File k is what --count 1 --seed (seed + k - 1) writes, under the plain name.
    const auto one = runShapevo("sample " + dir.file("ab.grammar") + " --seed 6 -o " + dir.file("one.obj") + " --genome " +
                                dir.file("one.genome"));
    ASSERT_EQ(one.exitCode, 0) << one.output;
    EXPECT_EQ(readFile(dir.file("one.obj")), readFile(dir.file("m-002.obj")));
    EXPECT_EQ(readFile(dir.file("one.genome")), readFile(dir.file("g-002.genome")));
}

TEST(SampleCount, FollowsTheSlotProbabilities) {
    TempDir dir;
    writeFile(dir.file("ab.grammar"), kSampleCountAB);
    const auto r = runShapevo("sample " + dir.file("ab.grammar") + " --count 40 -o " + dir.file("m.ply"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(countOf(r.output, "sampled "), 40u) << r.output;
    EXPECT_TRUE(fs::exists(dir.file("m-040.ply")));
    // B (prob 0.95) is in most files, A (prob 0.05) in few: 2 or 3 genes, rarely 1.
    EXPECT_GE(countOf(r.output, "sampled 2 genes") + countOf(r.output, "sampled 3 genes"), 30u) << r.output;
    EXPECT_LE(countOf(r.output, "sampled 3 genes"), 10u) << r.output;
}

TEST(SampleCount, AnyExistingOutputIsRefusedBeforeAnythingIsWritten) {
    TempDir dir;
    writeFile(dir.file("ab.grammar"), kSampleCountAB);
    writeFile(dir.file("m-003.obj"), "keep");
    const auto r = runShapevo("sample " + dir.file("ab.grammar") + " --count 3 -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + dir.file("m-003.obj") + ": already exists"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("m-001.obj")));
    EXPECT_EQ(readFile(dir.file("m-003.obj")), "keep");

    writeFile(dir.file("g-002.genome"), "keep");
    const auto g = runShapevo("sample " + dir.file("ab.grammar") + " --count 2 -o " + dir.file("n.obj") + " --genome " +
                              dir.file("g.genome"));
    EXPECT_EQ(g.exitCode, 2) << g.output;
    EXPECT_NE(g.output.find(dir.file("g-002.genome") + ": already exists"), std::string::npos) << g.output;
    EXPECT_FALSE(fs::exists(dir.file("n-001.obj")));
    EXPECT_FALSE(fs::exists(dir.file("g-001.genome")));
}

TEST(SampleCount, BadCountsAreExitTwo) {
    TempDir dir;
    writeFile(dir.file("ab.grammar"), kSampleCountAB);
    for (const std::string count : {"0", "-1", "abc", "", "1000001", "99999999999"}) {
        const auto r = runShapevo("sample " + dir.file("ab.grammar") + " --count '" + count + "' -o " + dir.file("m.obj"));
        EXPECT_EQ(r.exitCode, 2) << count << ": " << r.output;
        EXPECT_NE(r.output.find("shapevo: error: --count: expected a whole number of files from 1 to 1000000"),
                  std::string::npos)
            << count << ": " << r.output;
        EXPECT_FALSE(fs::exists(dir.file("m.obj"))) << count;
        EXPECT_FALSE(fs::exists(dir.file("m-001.obj"))) << count;
    }
}

TEST(SampleCount, AWindowNoDerivationMeetsIsExitTwoAndWritesNothing) {
    TempDir dir;
    writeFile(dir.file("small.grammar"), "start S\nrule S { box child A prob 0.5 max 2 }\nrule A { box }\n");  // <= 3 genes
    const auto r = runShapevo("sample " + dir.file("small.grammar") + " --count 2 --min-genes 4 -o " + dir.file("m.obj") +
                              " --genome " + dir.file("g.genome"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: --min-genes/--max-genes: no derivation of " + dir.file("small.grammar") +
                            " with 4 to 100 genes in 10000 draws (seed 1)"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir.file("m-001.obj")));
    EXPECT_FALSE(fs::exists(dir.file("g-001.genome")));

    // A reachable window is met by drawing again: exactly 3 genes, both A positions expressed.
    const auto ok = runShapevo("sample " + dir.file("small.grammar") + " --min-genes 3 -o " + dir.file("three.obj"));
    ASSERT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_NE(ok.output.find("sampled 3 genes, 3 primitives (seed 1"), std::string::npos) << ok.output;
}

}  // namespace
}  // namespace shapevo
