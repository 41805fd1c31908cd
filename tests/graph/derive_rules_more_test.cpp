// More of the derivation's semantic rules (graph-grammar README, section 2), each on a small
// grammar written here: deletion that leaves dangling edges, a kept edge re-attached to a new
// vertex, automatic positions without a directed edge, geometric ordering (the original's quirk
// and the fix), generation: oldest, priorities with their limits, option weights.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/input_error.hpp"
#include "graph/auto_position.hpp"
#include "graph/derive.hpp"
#include "graph/matcher.hpp"
#include "graph/read_graph_grammar.hpp"
#include "seeded_derivation.hpp"

namespace derive_rules_more_test {

using namespace shapevo::graph;

DeriveResult run(const std::string& text, std::uint64_t seed, std::int64_t steps = 0, DeriveLimits limits = {}) {
    return test_support::deriveSeeded(parseGraphGrammar(text, "rules.yml"), seed, steps, limits);
}

// Host: a -e- b. The production deletes the vertex labelled 'cut' but keeps the edge.
const char* kDangle = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0, label: cut}}
    - {id: 3, attr: {x: 1, y: 0, label: keep}}
    edges:
    - {id: 4, vertex1: 2, vertex2: 3, attr: {}}
productions:
  cut:
    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0, label: "attr == 'cut'"}}
      - {id: 13, attr: {x: 1, y: 0}}
      edges:
      - {id: 14, vertex1: 12, vertex2: 13, attr: {}}
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {13: 23, 14: 24}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 1, y: 0}}
        edges:
        - {id: 24, vertex1: null, vertex2: 23, attr: {state: "'loose'"}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, DeletingAVertexLeavesItsKeptEdgeDangling) {
    const DeriveResult r = run(kDangle, 1);
    EXPECT_EQ(r.steps, 1);
    EXPECT_EQ(r.graph.liveVertices(), 1u);
    EXPECT_EQ(r.graph.liveEdges(), 1u);
    EXPECT_EQ(r.graph.danglingEdges(), 1u);
    EXPECT_EQ(r.graph.elements(), 2u);  // a dangling edge counts as an element
    const HostEdge& e = r.graph.edge(0);
    EXPECT_TRUE(e.alive);
    EXPECT_EQ(e.vertex1, kNoVertex);
    EXPECT_EQ(e.vertex2, 1u);
}

// Host: a -e- b. The edge is kept but its daughter image ends at a new vertex c: e re-attaches.
const char* kReattach = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0, label: a}}
    - {id: 3, attr: {x: 2, y: 0, label: b}}
    edges:
    - {id: 4, vertex1: 2, vertex2: 3, attr: {label: e}}
productions:
  split:
    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0, label: "attr == 'a'"}}
      - {id: 13, attr: {x: 2, y: 0}}
      edges:
      - {id: 14, vertex1: 12, vertex2: 13, attr: {label: "attr == 'e'"}}
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {12: 23, 13: 24, 14: 26}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 0, y: 0, label: "'done'"}}
        - {id: 24, attr: {x: 2, y: 0}}
        - {id: 25, attr: {x: 1, y: 0, label: "'c'"}}
        edges:
        - {id: 26, vertex1: 23, vertex2: 25, attr: {}}
        - {id: 27, vertex1: 25, vertex2: 24, attr: {label: "'new'"}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, AKeptEdgeEndingAtANewDaughterVertexIsReattachedToIt) {
    const DeriveResult r = run(kReattach, 1);
    ASSERT_EQ(r.steps, 1);
    EXPECT_EQ(r.graph.liveVertices(), 3u);
    EXPECT_EQ(r.graph.liveEdges(), 2u);
    const HostEdge& kept = r.graph.edge(0);
    ASSERT_TRUE(kept.alive);
    EXPECT_EQ(kept.vertex1, 0u);
    EXPECT_EQ(kept.vertex2, 2u);  // the new vertex c, no longer b
    // Automatic position: the barycentres count the kept edge's ends — in the daughter (0,0),
    // (2,0) and the edge's (0,0), (1,0): 0.75; in the host (0,0), (2,0), (0,0), (2,0): 1. So c,
    // drawn at 1, lands at 1 + (1 - 0.75) = 1.25.
    const HostVertex& c = r.graph.vertex(2);
    EXPECT_NEAR(c.position.x, 1.25, 1e-12);
    EXPECT_NEAR(c.position.y, 0.0, 1e-12);
    // b keeps only the new edge; c has both.
    EXPECT_EQ(r.graph.vertex(1).edges.size(), 1u);
    EXPECT_EQ(r.graph.vertex(2).edges.size(), 2u);
}

TEST(GraphDeriveRulesMore, RegressionAngleIsTheOriginalsLeastSquaresLine) {
    EXPECT_NEAR(regressionAngle({{0, 0}, {1, 1}, {2, 2}}), M_PI / 4, 1e-12);
    EXPECT_NEAR(regressionAngle({{0, 0}, {1, 0}, {2, 0}}), 0.0, 1e-12);
    // Steep (σy/σx > 2): x regressed on y; vertical is π/2.
    EXPECT_NEAR(regressionAngle({{0, 0}, {0, 1}, {0, 2}}), M_PI / 2, 1e-12);
    EXPECT_NEAR(regressionAngle({{0, 0}, {0.1, 1}, {0.2, 2}}), std::atan2(1.0, 0.1), 1e-12);
    // Undirected: a line running down-right has a negative angle, not one near π.
    EXPECT_NEAR(regressionAngle({{0, 2}, {1, 1}, {2, 0}}), -M_PI / 4, 1e-12);
    EXPECT_EQ(regressionAngle({{3, 3}}), 0.0);
}

// Without a directed edge, a new vertex is placed by the regression lines: the mother graph is
// two vertices on the x axis; the host's are on the line y = x, twice as far apart.
const char* kUndirected = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0}}
    - {id: 3, attr: {x: 2, y: 2}}
    edges:
    - {id: 4, vertex1: 2, vertex2: 3, attr: {n: 0}}
productions:
  mark:
    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0}}
      - {id: 13, attr: {x: 1, y: 0}}
      edges:
      - {id: 14, vertex1: 12, vertex2: 13, attr: {n: "attr == 0"}}
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {12: 23, 13: 24, 14: 26}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 0, y: 0}}
        - {id: 24, attr: {x: 1, y: 0}}
        - {id: 25, attr: {x: 0.5, y: 0}}
        edges:
        - {id: 26, vertex1: 23, vertex2: 24, attr: {n: 1}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, WithoutADirectedEdgeTheRegressionLinesTurnAndTheExtentsScale) {
    const DeriveResult r = run(kUndirected, 1);
    ASSERT_EQ(r.steps, 1);
    const HostVertex& m = r.graph.vertex(2);
    EXPECT_NEAR(m.position.x, 1.0, 1e-12);
    EXPECT_NEAR(m.position.y, 1.0, 1e-12);
}

// Two productions at priorities 0 and 1; priority 0 is limited to 3 applications, the whole
// derivation to 10. Both always apply (a wildcard vertex, nothing deleted).
const char* kPriorities = R"(
options:
  max_derivations: {0: 3, all: 10}
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0}}
productions:
  first:
    id: 10
    priority: 0
    mother_graph: {id: 11, vertices: [{id: 12, attr: {x: 0, y: 0}}]}
    mappings:
    - {id: 13, mother_graph: 11, mapping: {id: 14, dict: {12: 16}},
       daughter_graph: {id: 15, vertices: [{id: 16, attr: {x: 0, y: 0}}, {id: 17, attr: {x: 1, y: 0, kind: "'first'"}}]}}
  second:
    id: 20
    priority: 1
    mother_graph: {id: 21, vertices: [{id: 22, attr: {x: 0, y: 0}}]}
    mappings:
    - {id: 23, mother_graph: 21, mapping: {id: 24, dict: {22: 26}},
       daughter_graph: {id: 25, vertices: [{id: 26, attr: {x: 0, y: 0}}, {id: 27, attr: {x: 1, y: 0, kind: "'second'"}}]}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, LowerPrioritiesRunFirstUntilTheirLimitThenTheGlobalLimitStops) {
    for (std::uint64_t seed : {1, 2, 3}) {
        const DeriveResult r = run(kPriorities, seed);
        EXPECT_EQ(r.steps, 10);
        EXPECT_EQ(r.stop, DeriveResult::Stop::StepLimit);
        EXPECT_EQ(r.fired[0], 3);
        EXPECT_EQ(r.fired[1], 7);
        // The first three new vertices are the first production's.
        const GraphGrammar g = parseGraphGrammar(kPriorities, "rules.yml");
        const AttrKey kind = g.names.find("kind");
        for (ElementId v = 1; v <= 3; ++v) EXPECT_EQ(toText(*r.graph.vertex(v).attrs.find(kind)), "first");
        EXPECT_EQ(toText(*r.graph.vertex(4).attrs.find(kind)), "second");
    }
}

// One production, two options weighted 3 : 1.
const char* kWeights = R"(
options:
  max_derivations: {all: 4000}
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0, root: 1}}
productions:
  grow:
    id: 10
    mother_graph: {id: 11, vertices: [{id: 12, attr: {x: 0, y: 0, root: "attr == 1"}}]}
    mappings:
    - {id: 13, mother_graph: 11, weight: 3, mapping: {id: 14, dict: {12: 16}},
       daughter_graph: {id: 15, vertices: [{id: 16, attr: {x: 0, y: 0}}, {id: 17, attr: {x: 1, y: 0, kind: "'heavy'"}}]}}
    - {id: 23, mother_graph: 11, weight: 1, mapping: {id: 24, dict: {12: 26}},
       daughter_graph: {id: 25, vertices: [{id: 26, attr: {x: 0, y: 0}}, {id: 27, attr: {x: 1, y: 0, kind: "'light'"}}]}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, OptionsAreDrawnByWeight) {
    const DeriveResult r = run(kWeights, 5);
    const GraphGrammar g = parseGraphGrammar(kWeights, "rules.yml");
    const AttrKey kind = g.names.find("kind");
    int heavy = 0, light = 0;
    for (const HostVertex& v : r.graph.vertices())
        if (const Value* k = v.attrs.find(kind)) (toText(*k) == "heavy" ? heavy : light)++;
    EXPECT_EQ(heavy + light, 4000);
    EXPECT_NEAR(double(heavy) / 4000.0, 0.75, 0.03);  // binomial sd 0.007: 4 sd
}

// generation: oldest — a chain grows from its oldest end only: with "oldest", every step extends
// a leaf of the lowest generation, so the tree fills level by level (a breadth-first tree).
const char* kOldest = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0, leaf: 1}}
productions:
  fork:
    id: 10
    mother_graph: {id: 11, vertices: [{id: 12, attr: {x: 0, y: 0, leaf: "attr == 1"}}]}
    mappings:
    - id: 13
      mother_graph: 11
      conditions: {generation: oldest}
      mapping: {id: 14, dict: {12: 16}}
      daughter_graph:
        id: 15
        vertices:
        - {id: 16, attr: {x: 0, y: 0, leaf: 0}}
        - {id: 17, attr: {x: -1, y: 1, leaf: 1}}
        - {id: 18, attr: {x: 1, y: 1, leaf: 1}}
        edges:
        - {id: 19, vertex1: 16, vertex2: 17, attr: {}}
        - {id: 20, vertex1: 16, vertex2: 18, attr: {}}
result_graphs: {}
)";

TEST(GraphDeriveRulesMore, OldestExpandsTheLowestGenerationFirst) {
    for (std::uint64_t seed : {1, 2, 3, 4}) {
        // 1 + 2 + 4 = 7 steps complete three levels: every leaf is then of generation 3.
        const DeriveResult r = run(kOldest, seed, 7);
        const GraphGrammar g = parseGraphGrammar(kOldest, "rules.yml");
        const AttrKey leaf = g.names.find("leaf");
        for (const HostVertex& v : r.graph.vertices()) {
            const Value* l = v.attrs.find(leaf);
            const bool isLeaf = l && truthy(*l);
            if (isLeaf) EXPECT_EQ(v.generation, 3) << "seed " << seed;
            else EXPECT_LE(v.generation, 2) << "seed " << seed;
        }
    }
}

// Geometric ordering: four unconnected mother vertices at x = 0, 3, 2, 1 (mapped in that file
// order) over four host vertices at x = 0, 1, 2, 3. The last one (x 1) is compared with the
// nearest mapped vertex before it (x 0) and — the original's quirk — the *farthest* mapped one
// after it (x 3), not the nearest (x 2). So the quirk lets the middle two swap: 2 matches; the
// fix keeps the full order: 1 match.
const char* kOrdering = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0}}
    - {id: 3, attr: {x: 1, y: 0}}
    - {id: 4, attr: {x: 2, y: 0}}
    - {id: 5, attr: {x: 3, y: 0}}
productions:
  order:
    id: 10
    conditions: {.geometric_ordering: 'True'}
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0}}
      - {id: 13, attr: {x: 3, y: 0}}
      - {id: 14, attr: {x: 2, y: 0}}
      - {id: 15, attr: {x: 1, y: 0}}
    mappings:
    - {id: 16, mother_graph: 11, mapping: {id: 17, dict: {12: 19, 13: 20, 14: 21, 15: 22}},
       daughter_graph: {id: 18, vertices: [{id: 19, attr: {x: 0, y: 0}}, {id: 20, attr: {x: 3, y: 0}},
                                           {id: 21, attr: {x: 2, y: 0}}, {id: 22, attr: {x: 1, y: 0}}]}}
result_graphs: {}
)";

std::size_t orderingMatches(bool fixed, bool ordering) {
    std::string text = kOrdering;
    if (!ordering) text.replace(text.find("'True'"), 6, "'False'");
    const GraphGrammar g = parseGraphGrammar(text, "rules.yml");
    SeededDraws draws(1);
    Matcher m(g, g.hosts[0].graph, {}, draws, MatchBudget{}, fixed);
    m.initialize();
    return m.count(0);
}

TEST(GraphDeriveRulesMore, GeometricOrderingReproducesTheOriginalsFarthestAfterQuirkAndFixesIt) {
    EXPECT_EQ(orderingMatches(false, false), 24u);  // no ordering: every injective map
    EXPECT_EQ(orderingMatches(false, true), 2u);    // the original's comparisons
    EXPECT_EQ(orderingMatches(true, true), 1u);     // the intended order
}

}  // namespace derive_rules_more_test
