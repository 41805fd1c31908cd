// The README's first run cannot go stale: this test runs the command the README shows (from the
// repository root, into a temporary output folder) and checks that every line of the README's
// printed block is what the binary prints, in order, with the timing fields (evals/s, elapsed,
// ETA, "in X s"), the thread count and the output folder set aside. A "..." line in the block
// stands for any number of lines the README leaves out.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runCommand;
using test::sourcePath;
using test::TempDir;

const char* const kReadmeDemoBegin = "<!-- readme-demo: begin";
const char* const kReadmeDemoEnd = "<!-- readme-demo: end";

/// A printed line without what differs from machine to machine and run to run.
std::string readmeDemoNormalized(std::string line) {
    static const std::vector<std::pair<std::regex, std::string>> rules = {
        {std::regex(R"([0-9]+ evals/s)"), "<N> evals/s"},
        {std::regex(R"(elapsed [0-9hm.]+s)"), "elapsed <T>"},
        {std::regex(R"(ETA [0-9hm.]+s)"), "ETA <T>"},
        {std::regex(R"( in [0-9hm.]+s -> .*$)"), " in <T> -> <OUT>"},
        {std::regex(R"(x [0-9]+ thread\(s\))"), "x <N> thread(s)"},
        {std::regex(R"(, output .*$)"), ", output <OUT>"},
    };
    for (const auto& [pattern, replacement] : rules) line = std::regex_replace(line, pattern, replacement);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    return line;
}

struct ReadmeDemoBlock {
    std::string command;             ///< what follows "$ " on the block's first line
    std::vector<std::string> lines;  ///< the printed lines, "..." where lines are left out
};

/// The fenced block between the readme-demo markers of `readme`; empty command if there is none.
ReadmeDemoBlock readmeDemoBlock(const std::string& readme) {
    ReadmeDemoBlock block;
    const auto begin = readme.find(kReadmeDemoBegin), end = readme.find(kReadmeDemoEnd);
    if (begin == std::string::npos || end == std::string::npos || end < begin) return block;
    std::vector<std::string> lines = test::splitLines(readme.substr(begin, end - begin));
    bool inFence = false;
    for (const std::string& line : lines) {
        if (line.rfind("```", 0) == 0) {
            if (inFence) break;
            inFence = true;
            continue;
        }
        if (!inFence) continue;
        if (block.command.empty() && line.rfind("$ ", 0) == 0) block.command = line.substr(2);
        else block.lines.push_back(line);
    }
    return block;
}

/// Where the shown lines differ from the printed ones ("" when each shown line is printed, in
/// order, and lines are skipped only where the block has "...").
std::string readmeDemoMismatch(const std::vector<std::string>& shown, const std::vector<std::string>& printed) {
    std::size_t next = 0;
    bool mayskip = false;
    for (const std::string& line : shown) {
        if (line == "...") {
            mayskip = true;
            continue;
        }
        const std::string want = readmeDemoNormalized(line);
        std::size_t at = next;
        while (at < printed.size() && readmeDemoNormalized(printed[at]) != want) {
            if (!mayskip) return "the README shows\n  " + line + "\nwhere the binary prints\n  " + printed[at];
            ++at;
        }
        if (at == printed.size()) return "the README shows a line the binary does not print (or not in this order):\n  " + line;
        next = at + 1;
        mayskip = false;
    }
    if (!mayskip && next != printed.size()) return "the binary prints more than the README shows, from:\n  " + printed[next];
    return {};
}

TEST(ReadmeDemo, ThePrintedBlockIsWhatTheDemoPrints) {
    const ReadmeDemoBlock block = readmeDemoBlock(readFile(sourcePath("README.md")));
    ASSERT_EQ(block.command, "build/shapevo run configs/spaceship.toml") << "README.md: no demo block between the readme-demo markers";
    ASSERT_GE(block.lines.size(), 3u);
    TempDir dir;
    // From the repository root, as a user types it; only the output folder differs. The block is
    // the run's standard output: its stderr is dropped inside the subshell (runCommand adds 2>&1
    // after the command), so a sanitizer build's own report at exit does not count.
    const auto r = runCommand("(cd " + std::string(SHAPEVO_SOURCE_DIR) + " && " + SHAPEVO_BIN + " run configs/spaceship.toml --out " +
                              dir.file("run") + " 2>/dev/null)");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string mismatch = readmeDemoMismatch(block.lines, test::splitLines(r.output));
    EXPECT_EQ(mismatch, "") << "README.md's first run is stale; paste what the command prints now:\n" << r.output;
}

TEST(ReadmeDemo, TheComparisonCatchesAnAlteredLineAndIgnoresTimings) {
    const std::vector<std::string> printed = {
        "head, 1 island(s) x 2 thread(s), seed 1, output /tmp/x",
        "gen  1/3  best 0.5  12 evals/s  elapsed 0.01s  ETA 0.50s",
        "gen  2/3  best 0.6  13 evals/s  elapsed 0.02s  ETA 0.40s",
        "gen  3/3  best 0.7  14 evals/s  elapsed 0.03s  ETA 0.00s",
        "done: best fitness 0.7, 9 evaluations in 0.04s -> /tmp/x/"};
    const std::vector<std::string> same = {
        "head, 1 island(s) x 8 thread(s), seed 1, output runs/spaceship", "gen  1/3  best 0.5  99 evals/s  elapsed 1.00s  ETA 9.00s",
        "...", "gen  3/3  best 0.7  1 evals/s  elapsed 0.30s  ETA 0.00s", "done: best fitness 0.7, 9 evaluations in 2m01s -> runs/spaceship/"};
    EXPECT_EQ(readmeDemoMismatch(same, printed), "");
    std::vector<std::string> altered = same;
    altered[3] = "gen  3/3  best 0.8  1 evals/s  elapsed 0.30s  ETA 0.00s";
    EXPECT_NE(readmeDemoMismatch(altered, printed), "");
    std::vector<std::string> noEllipsis = same;
    noEllipsis.erase(noEllipsis.begin() + 2);
    EXPECT_NE(readmeDemoMismatch(noEllipsis, printed), "") << "lines left out without a \"...\"";
    std::vector<std::string> shorter(same.begin(), same.end() - 1);
    EXPECT_NE(readmeDemoMismatch(shorter, printed), "") << "the last line left out";
}

}  // namespace
}  // namespace shapevo
