// search.diagnostics end to end: the run writes diagnostics.csv (a header and a row per
// generation whose operator counts add up to the generation's children) and is otherwise the same
// run as without it (best.genome and curve.csv identical); the key takes only true or false.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::curveWithoutTime;
using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    return cells;
}

TEST(Diagnostics, TheRunWritesARowPerGenerationAndIsOtherwiseTheSame) {
    TempDir dir;
    const std::string base = "run " + sourcePath("configs/tree-sketch.toml") +
                             " --seed 2 -q --set run.wall_time=0 --set ga.generations=30 --out ";
    const auto plain = runShapevo(base + dir.file("plain"));
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    const auto diag = runShapevo(base + dir.file("diag") + " --set search.diagnostics=true");
    ASSERT_EQ(diag.exitCode, 0) << diag.output;
    EXPECT_EQ(readFile(dir.file("plain/best.genome")), readFile(dir.file("diag/best.genome")));
    EXPECT_EQ(curveWithoutTime(readFile(dir.file("plain/curve.csv"))), curveWithoutTime(readFile(dir.file("diag/curve.csv"))));
    EXPECT_FALSE(std::filesystem::exists(dir.file("plain/diagnostics.csv")));

    std::stringstream csv(readFile(dir.file("diag/diagnostics.csv")));
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> header = split(line);
    ASSERT_EQ(header.size(), 11u + 3u * 7u);  // 7 operators (grow ... copy) x better, equal, worse
    EXPECT_EQ(header[5], "distinct_genomes");
    EXPECT_EQ(header.back(), "copy_worse");
    int rows = 0;
    while (std::getline(csv, line)) {
        const std::vector<std::string> cells = split(line);
        ASSERT_EQ(cells.size(), header.size()) << line;
        ++rows;
        EXPECT_EQ(std::stoi(cells[0]), rows);
        long children = 0, refined = 0;
        for (std::size_t i = 11; i < cells.size(); ++i) (header[i].rfind("refine_", 0) == 0 ? refined : children) += std::stol(cells[i]);
        // tree-sketch with the default (hybrid) search: population 150 in islands of 38, 38, 37, 37
        // keeping 8, 8, 7, 7 elites -> 120 children a generation (none in the first), and at most
        // 19 local moves of elites per island (hybrid_refine 0.5)
        EXPECT_EQ(children, rows == 1 ? 0 : 120) << line;
        EXPECT_LE(refined, 76) << line;
        if (rows > 1) EXPECT_GT(refined, 50) << line;
        EXPECT_LE(std::stoul(cells[6]), std::stoul(cells[5]));  // structures <= genomes
        EXPECT_LE(std::stoul(cells[5]), 150u);
    }
    EXPECT_EQ(rows, 30);
}

TEST(Diagnostics, TheKeyTakesOnlyTrueOrFalse) {
    TempDir dir;
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " -q --set search.diagnostics=1 --out " + dir.file("x"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("search.diagnostics must be true or false"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace shapevo
