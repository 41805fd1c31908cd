// `shapevo graph FILE.grammar|.rule|.pcg -o OUT.dot|.svg|.png` end to end: the .dot of every shipped
// grammar and rule file names every rule and every slot, that of every shipped graph file every
// node (and its summary counts nodes, not rules); .svg and .png are valid files; the
// shipped tree's recursion edges are dashed and its Branch instances starred; bad input (a
// grammar or output extension it does not take, a missing file, a grammar error, an existing or
// unwritable output) is exit 2 with the file in the message and nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/pcg/pcg_graph.hpp"

namespace shapevo {
namespace graph_command_test_helpers {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

std::size_t occurrencesOf(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

}  // namespace graph_command_test_helpers

using namespace graph_command_test_helpers;

TEST(GraphCommand, TheDotOfEveryShippedGrammarNamesEveryRuleAndSlot) {
    TempDir dir;
    for (const std::string& path : test::shippedGrammarFiles()) {
        const std::string out = dir.file(std::filesystem::path(path).filename().string() + ".dot");  // window.pcg, window.grammar
        const auto r = runShapevo("graph " + path + " -o " + out);
        ASSERT_EQ(r.exitCode, 0) << path << "\n" << r.output;
        EXPECT_NE(r.output.find("wrote " + out), std::string::npos) << r.output;
        const std::string dot = readFile(out);
        if (std::filesystem::path(path).extension() == ".pcg") {  // the graph itself: its nodes
            const pcg::FlatGraph graph = pcg::buildPcgGraph(readFile(path), path);
            ASSERT_FALSE(graph.nodes.empty()) << path;
            for (const pcg::FlatNode& node : graph.nodes) EXPECT_NE(dot.find(" " + node.name), std::string::npos) << path << ": node " << node.name;
            EXPECT_NE(r.output.find("(" + std::to_string(graph.nodes.size()) + " nodes, "), std::string::npos) << r.output;
            continue;
        }
        EXPECT_NE(r.output.find(" rules, "), std::string::npos) << r.output;
        const Grammar g = loadGrammar(path);
        for (const Rule& rule : g.rules) {
            EXPECT_NE(dot.find(" " + rule.name), std::string::npos) << path << ": rule " << rule.name;
            for (std::size_t k = 0; k < rule.slots.size(); ++k) {
                const std::string label = "slot " + std::to_string(k + 1) + " \u00b7 edge " + std::to_string(rule.slots[k].edge);
                EXPECT_NE(dot.find("[label=\"" + label), std::string::npos) << path << ": " << rule.name << " " << label;
            }
        }
    }
}

TEST(GraphCommand, SvgAndPngAreValidPictures) {
    TempDir dir;
    auto r = runShapevo("graph " + sourcePath("grammars/castle.grammar") + " -o " + dir.file("castle.svg"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string svg = readFile(dir.file("castle.svg"));
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    r = runShapevo("graph " + sourcePath("grammars/castlemaker/toy-castle.rule") + " -o " + dir.file("toy.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("Warning"), std::string::npos) << "nothing but the summary: " << r.output;
    const std::string png = readFile(dir.file("toy.png"));
    ASSERT_GT(png.size(), 100u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(GraphCommand, TheTreesRecursionIsDashedAndItsBranchesStarred) {
    TempDir dir;
    const auto r = runShapevo("graph " + sourcePath("grammars/tree.grammar") + " -o " + dir.file("tree.dot"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("(4 rules, 12 edges, 6 cyclic, 3 on a loop;"), std::string::npos) << r.output;
    const std::string dot = readFile(dir.file("tree.dot"));
    EXPECT_NE(dot.find("<TD>1 Trunk</TD>"), std::string::npos) << dot;
    EXPECT_NE(dot.find("<TD>2 Branch(0, 120) *</TD>"), std::string::npos) << dot;
    EXPECT_NE(dot.find("<TD>3 Branch(120, 240) *</TD>"), std::string::npos) << dot;
    EXPECT_NE(dot.find("<TD>4 Branch(240, 360) *</TD>"), std::string::npos) << dot;
    EXPECT_EQ(occurrencesOf(dot, "style=dashed"), 6u) << dot;
}

TEST(GraphCommand, BadInputIsExit2NamingTheFileAndWritesNothing) {
    TempDir dir;
    writeFile(dir.file("bad.grammar"), "start A\nrule A {\n  box\n  child Nowhere\n}\n");
    writeFile(dir.file("ok.grammar"), "start A\nrule A {\n  box\n}\n");
    writeFile(dir.file("ok.txt"), "start A\nrule A {\n  box\n}\n");
    writeFile(dir.file("exists.svg"), "keep");
    writeFile(dir.file("plain-file"), "");
    struct Case {
        std::string args, named, says;
    };
    const std::vector<Case> cases{
        {dir.file("ok.txt") + " -o " + dir.file("a.svg"), dir.file("ok.txt"), "unknown grammar file extension '.txt'"},
        {dir.file("ok.grammar") + " -o " + dir.file("a.jpg"), dir.file("a.jpg"), "unknown output extension '.jpg'"},
        {dir.file("ok.grammar") + " -o " + dir.file("a"), dir.file("a"), "has no file extension"},
        {dir.file("missing.grammar") + " -o " + dir.file("a.svg"), dir.file("missing.grammar"), "cannot open grammar file"},
        {dir.file("bad.grammar") + " -o " + dir.file("a.svg"), dir.file("bad.grammar") + ":4:", "Nowhere"},
        {dir.file("ok.grammar") + " -o " + dir.file("exists.svg"), dir.file("exists.svg"), "already exists"},
        {dir.file("ok.grammar") + " -o " + dir.file("plain-file/a.dot"), dir.file("plain-file/a.dot"), ""},
    };
    for (const Case& c : cases) {
        const auto r = runShapevo("graph " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find("shapevo: error: " + c.named), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.svg")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.jpg")));
    EXPECT_EQ(readFile(dir.file("exists.svg")), "keep");
}

TEST(GraphCommand, HelpSaysWhatItReadsAndWrites) {
    const auto r = runShapevo("graph --help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* word : {".grammar", ".rule", ".dot", ".svg", ".png", "must not exist"})
        EXPECT_NE(r.output.find(word), std::string::npos) << word << "\n" << r.output;
}

}  // namespace shapevo
