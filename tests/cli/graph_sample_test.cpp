// `shapevo sample FILE.yml` end to end on tests/data/graph/sprout.yml (written for these tests):
// the line per derivation, SVG and PNG outputs, the same bytes for one seed, numbered files with
// --count, and exit 2 with nothing written for options that only tree grammars take, options
// that only graph grammars take given to a tree grammar, a bad value or an existing output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../image/png_read.hpp"
#include "../test_support.hpp"

namespace graph_sample_cli_test {

using shapevo::test::readFile;
using shapevo::test::runShapevo;
using shapevo::test::sourcePath;
using shapevo::test::TempDir;

namespace fs = std::filesystem;

std::string sprout() { return sourcePath("tests/data/graph/sprout.yml"); }

TEST(GraphSampleCommand, WritesTheSvgAndPrintsTheCounts) {
    TempDir dir;
    const auto r = runShapevo("sample " + sprout() + " --seed 3 -o " + dir.file("a.svg"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output, "sprout.yml seed 3: 5 steps, 6 vertices, 5 edges (0 dangling), 11 elements -> " + dir.file("a.svg") + "\n");
    const std::string svg = readFile(dir.file("a.svg"));
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("<rect fill=\"green\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("<line stroke=\"red\" stroke-linecap=\"round\""), std::string::npos) << svg;
    // The default margin, half a model unit: the box of x = 0 is 35.43307 user units wide.
    EXPECT_NE(svg.find("width=\"35.43307\""), std::string::npos) << svg;
}

TEST(GraphSampleCommand, OneSeedGivesTheSameBytes) {
    TempDir dir;
    ASSERT_EQ(runShapevo("sample " + sprout() + " --seed 9 --margin 0 -o " + dir.file("a.svg")).exitCode, 0);
    ASSERT_EQ(runShapevo("sample " + sprout() + " --seed 9 --margin 0 -o " + dir.file("b.svg")).exitCode, 0);
    EXPECT_EQ(readFile(dir.file("a.svg")), readFile(dir.file("b.svg")));
    EXPECT_NE(readFile(dir.file("a.svg")).find("width=\"0.0\""), std::string::npos) << "margin 0: a line has no width";
}

TEST(GraphSampleCommand, CountAndStepsNumberTheFiles) {
    TempDir dir;
    const auto r = runShapevo("sample " + sprout() + " --count 2 --steps 2 -o " + dir.file("s.svg"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("sprout.yml seed 1: 2 steps, 3 vertices, 2 edges (0 dangling), 5 elements -> " + dir.file("s-001.svg")),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("sprout.yml seed 2: 2 steps"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir.file("s-002.svg")));
}

TEST(GraphSampleCommand, WritesAPngOfTheSizeAsked) {
    TempDir dir;
    const auto r = runShapevo("sample " + sprout() + " --size 64x128 -o " + dir.file("p.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    bool ok = false;
    const auto image = shapevo::test::readPngRgba(dir.file("p.png"), ok);
    ASSERT_TRUE(ok);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 128);
}

TEST(GraphSampleCommand, RefusesOptionsThatDoNotApplyWithExit2) {
    TempDir dir;
    const std::string out = " -o " + dir.file("x.svg");
    for (const std::string& args : std::vector<std::string>{"--min-genes 2", "--max-genes 9", "--attr a=1",
                                                             "--size 64x64", "--steps -1", "--steps many", "--margin -1",
                                                             "--margin nan", "--seed x"}) {
        const auto r = runShapevo("sample " + sprout() + " " + args + out);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(args.substr(0, args.find(' '))), std::string::npos) << args << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir.file("x.svg")));
    const auto tree = runShapevo("sample " + sourcePath("grammars/spaceship.grammar") + " --steps 3 -o " + dir.file("m.obj"));
    EXPECT_EQ(tree.exitCode, 2) << tree.output;
    EXPECT_NE(tree.output.find("--steps: applies to graph grammars"), std::string::npos) << tree.output;
    const auto margin = runShapevo("sample " + sourcePath("grammars/spaceship.grammar") + " --margin 1 -o " + dir.file("m.obj"));
    EXPECT_EQ(margin.exitCode, 2) << margin.output;
    const auto obj = runShapevo("sample " + sprout() + " -o " + dir.file("m.obj"));
    EXPECT_EQ(obj.exitCode, 2) << obj.output;
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
}

TEST(GraphSampleCommand, NeverReplacesAFile) {
    TempDir dir;
    shapevo::test::writeFile(dir.file("s-002.svg"), "mine");
    const auto r = runShapevo("sample " + sprout() + " --count 2 -o " + dir.file("s.svg"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("already exists"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("s-001.svg")));
    EXPECT_EQ(readFile(dir.file("s-002.svg")), "mine");
}

}  // namespace graph_sample_cli_test
