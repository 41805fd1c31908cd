// The generator graph of a Grammar as a diagram (grammar/grammar_diagram.hpp): one node per rule
// (and per rule called only inline), one Child edge per slot alternative and one Inline edge per
// inline callee, one collective node per gather fed by its rule and its senders; cyclic edges, topological numbers and loop nodes as PCGR §3.4 / §3.5 give them,
// for a hand-made grammar and for the shipped tree (whose Branch instances call each other).
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/grammar_diagram.hpp"

namespace shapevo {
namespace grammar_diagram_test_helpers {

constexpr const char* kInlineAndRecursion = R"(
start A
rule A {
  box
  Trim
  child B prob 0.5
  Deco(0.5)
}
rule Trim { sphere }
rule B {
  cylinder
  child A prob 0.5 max 2
}
rule Deco(s) {
  size (s, s, s)
  sphere
}
)";

std::vector<std::string> nodeNames(const pcg::GraphDiagram& d) {
    std::vector<std::string> names;
    for (const pcg::DiagramNode& n : d.nodes) names.push_back(n.name);
    return names;
}

}  // namespace grammar_diagram_test_helpers

using namespace grammar_diagram_test_helpers;

TEST(GrammarDiagram, RulesSlotsAndInlineCallsWithTheirOrder) {
    const pcg::GraphDiagram d = grammarDiagram(parseGrammar(kInlineAndRecursion, "inline.grammar"));
    EXPECT_EQ(d.title, "inline.grammar");
    ASSERT_EQ(nodeNames(d), (std::vector<std::string>{"A", "Trim", "B", "Deco"})) << "rules by id, then inline-only rules";
    EXPECT_TRUE(d.nodes[0].start);
    EXPECT_EQ(d.nodes[0].ports.size(), 2u) << "in and slot 1";
    EXPECT_EQ(d.nodes[3].detail, "runs only inline (no gene of its own)");
    ASSERT_EQ(d.edges.size(), 4u);
    // A's slot, A's inline calls in the order written, B's slot
    EXPECT_EQ(d.edges[0].kind, pcg::EdgeKind::Child);
    EXPECT_EQ(d.edges[0].to, 2u);
    EXPECT_EQ(d.edges[0].fromPort, 1);
    EXPECT_EQ(d.edges[0].label.rfind("slot 1 \u00b7 edge ", 0), 0u) << d.edges[0].label;
    EXPECT_NE(d.edges[0].label.find("p 0.5"), std::string::npos) << d.edges[0].label;
    EXPECT_EQ(d.edges[1].kind, pcg::EdgeKind::Inline);
    EXPECT_EQ(d.edges[1].to, 1u);
    EXPECT_EQ(d.edges[2].kind, pcg::EdgeKind::Inline);
    EXPECT_EQ(d.edges[2].to, 3u);
    EXPECT_EQ(d.edges[3].kind, pcg::EdgeKind::Child);
    EXPECT_EQ(d.edges[3].to, 0u);
    EXPECT_NE(d.edges[3].label.find("\u00d72"), std::string::npos) << d.edges[3].label;
    // §3.5 from A: A -> B visited, B -> A closes the cycle
    EXPECT_FALSE(d.edges[0].cyclic);
    EXPECT_TRUE(d.edges[3].cyclic);
    EXPECT_FALSE(d.edges[1].cyclic || d.edges[2].cyclic);
    // §3.4: the source A, then Trim, B, Deco by file order
    std::vector<std::uint32_t> order;
    std::vector<bool> loop;
    for (const pcg::DiagramNode& n : d.nodes) {
        order.push_back(n.order);
        loop.push_back(n.loop);
    }
    EXPECT_EQ(order, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(loop, (std::vector<bool>{true, false, true, false}));
}

TEST(GrammarDiagram, TheShippedTreesBranchInstancesAreLoopNodes) {
    const pcg::GraphDiagram d = grammarDiagram(loadGrammar(test::sourcePath("grammars/tree.grammar")));
    ASSERT_EQ(nodeNames(d), (std::vector<std::string>{"Trunk", "Branch(0, 120)", "Branch(120, 240)", "Branch(240, 360)"}));
    ASSERT_EQ(d.edges.size(), 12u) << "three slots on each of the four rules";
    // Worked by hand from §3.5 (see tests/grammar/graph_order_test.cpp for the literal search):
    // from Trunk, B1 -> B2 -> B3 are followed; every edge into an instance already on the path is
    // cyclic, and the marks persist, so B1 -> B3 and Trunk's edges stay non-cyclic.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cyclic;
    for (const pcg::DiagramEdge& e : d.edges)
        if (e.cyclic) cyclic.emplace_back(e.from, e.to);
    EXPECT_EQ(cyclic, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{1, 1}, {2, 1}, {2, 2}, {3, 1}, {3, 2}, {3, 3}}));
    for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_EQ(d.nodes[v].order, v);
        EXPECT_EQ(d.nodes[v].loop, v > 0) << d.nodes[v].name;
    }
}

TEST(GrammarDiagram, EachGatherIsACollectiveNodeThatItsRuleAndItsSendersFeed) {
    const pcg::GraphDiagram d = grammarDiagram(loadGrammar(test::sourcePath("grammars/houses.grammar")));
    std::size_t gathers = 0;
    for (std::uint32_t v = 0; v < d.nodes.size(); ++v) {
        const pcg::DiagramNode& n = d.nodes[v];
        if (n.name != "gather facades") continue;
        ++gathers;
        ASSERT_EQ(n.ports.size(), 1u);
        EXPECT_EQ(n.ports[0].kind, pcg::PortKind::Collective);
        EXPECT_EQ(n.detail, "order by, keep first");
        std::size_t sends = 0, owner = 0;
        for (const pcg::DiagramEdge& e : d.edges) {
            if (e.to != v) continue;
            sends += e.label == "send facades" && e.toPort == 0;
            owner += e.label == "at the end of each run" && d.nodes[e.from].name == "House";
        }
        EXPECT_EQ(sends, 1u) << "House sends its sides";
        EXPECT_EQ(owner, 1u) << "House gathers them";
    }
    EXPECT_EQ(gathers, 1u);
    const pcg::GraphDiagram plain = grammarDiagram(loadGrammar(test::sourcePath("grammars/tree.grammar")));
    for (const pcg::DiagramNode& n : plain.nodes) EXPECT_EQ(n.name.rfind("gather ", 0), std::string::npos);
}

TEST(GrammarDiagram, AFileIsDrawnByItsFrontEndAndAnUnknownExtensionIsRefused) {
    const std::string rule = test::sourcePath("grammars/castlemaker/toy-castle.rule");
    const pcg::GraphDiagram d = grammarFileDiagram(rule);
    EXPECT_EQ(nodeNames(d), nodeNames(grammarDiagram(loadGrammar(rule))));
    EXPECT_FALSE(d.nodes.empty());
    test::TempDir dir;
    test::writeFile(dir.file("tree.txt"), "start A\nrule A {\n  box\n}\n");
    try {
        grammarFileDiagram(dir.file("tree.txt"));
        ADD_FAILURE() << "a .txt file was drawn";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.file("tree.txt"));
        EXPECT_NE(e.message().find("unknown grammar file extension '.txt'"), std::string::npos) << e.what();
    }
}

}  // namespace shapevo
