// The commands that take a grammar take a `.pcg` graph file: `shapevo translate` prints its
// shapevo-language text with the .pcg line of each rule, `shapevo sample` derives it, `shapevo
// graph` draws the graph itself (its nodes, ports and cyclic edges); a broken graph file is exit 2
// with its file:line:column.
#include <gtest/gtest.h>

#include <string>

#include "../test_support.hpp"

namespace shapevo {
namespace pcg_commands_test_helpers {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

}  // namespace pcg_commands_test_helpers

using namespace pcg_commands_test_helpers;

TEST(PcgCommands, TranslatePrintsTheShapevoTextWithTheGraphFileLine) {
    const auto r = runShapevo("translate " + sourcePath("grammars/pcg/window.pcg"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("start Window"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("rule Window {    # window.pcg:5"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("split y {"), std::string::npos) << r.output;
}

TEST(PcgCommands, SampleDerivesAGraphFile) {
    TempDir dir;
    const auto r = runShapevo("sample " + sourcePath("grammars/pcg/tree.pcg") + " --seed 3 -o " + dir.file("t.obj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readFile(dir.file("t.obj")).find("\nf "), std::string::npos);
}

TEST(PcgCommands, GraphDrawsTheNodesAndTheDashedCyclicEdge) {
    TempDir dir;
    const auto r = runShapevo("graph " + sourcePath("grammars/pcg/tree.pcg") + " -o " + dir.file("t.dot"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string dot = readFile(dir.file("t.dot"));
    for (const char* node : {"trunk", "wood", "lift", "fruit", "ground"}) EXPECT_NE(dot.find(node), std::string::npos) << node;
    EXPECT_NE(dot.find("dashed"), std::string::npos) << dot;
}

TEST(PcgCommands, ABrokenGraphFileIsExitTwoAtItsLine) {
    TempDir dir;
    writeFile(dir.file("bad.pcg"), "graph G\nin start : volume\nnode a = boxx()\nstart -> a\n");
    for (const char* command : {"translate", "sample", "graph"}) {
        const std::string out = std::string(command) == "graph" ? " -o " + dir.file("x.dot") : std::string(command) == "sample" ? " -o " + dir.file("x.obj") : "";
        const auto r = runShapevo(std::string(command) + " " + dir.file("bad.pcg") + out);
        EXPECT_EQ(r.exitCode, 2) << command << "\n" << r.output;
        EXPECT_NE(r.output.find("bad.pcg:3:10: unknown node operation 'boxx'"), std::string::npos) << command << "\n" << r.output;
    }
}

}  // namespace shapevo
