// What a daughter expression sees (graph-grammar README, section 2.5), each on a small grammar
// written here: `self_` with the keys set before it, `old` (the element before the step; None for
// a new one), per-run and per-application variables, `all` requirements, new_x / new_y, and a
// mother edge whose end is an editor helper (dangling: it matches an edge whatever its other end).
#include <gtest/gtest.h>

#include <string>

#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"
#include "seeded_derivation.hpp"

namespace derive_scope_test {

using namespace shapevo::graph;

struct Derived {
    GraphGrammar grammar;
    DeriveResult result;
    std::string text(ElementId v, const char* key) const {
        const Value* x = result.graph.vertex(v).attrs.find(grammar.names.find(key));
        return x ? toText(*x) : "<missing>";
    }
};

Derived derive(const std::string& yaml, std::uint64_t seed = 1, std::int64_t steps = 0) {
    Derived d{parseGraphGrammar(yaml, "scope.yml"), {}};
    d.result = test_support::deriveSeeded(d.grammar, seed, steps);
    return d;
}

// One vertex n = 5 becomes: itself (kept) with n = old n + 1, plus a new vertex that records
// what it saw. Once (max_derivations all: 1).
const char* kScope = R"(
global_vars: {base: '100'}
options: {max_derivations: {all: 1}}
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 1, y: 2, n: 5}}
productions:
  p:
    id: 10
    vectors: {P: 12}
    mother_graph: {id: 11, vertices: [{id: 12, attr: {x: 0, y: 0}}]}
    mappings:
    - id: 13
      mother_graph: 11
      mapping: {id: 14, dict: {12: 16}}
      attr_requirements:
        all: {host: 12}
      var_calc_instructions:
      - [once, 'base + 1', run]
      - [each, 'host.attr[''n''] * 10', application]
      - [each2, 'each + 1', application]
      daughter_graph:
        id: 15
        vertices:
        - {id: 16, attr: {x: 0, y: 0, n: 'old.attr[''n''] + 1', twice: 'self_.attr[''n''] * 2'}}
        - id: 17
          attr: {x: 1, y: 0, new_x: '7.5', new_y: 'P.y - 1',
                 was_none: 'old is None' , saw_run: once, saw_app: each2, saw_all: 'host.attr[''n'']',
                 first: '''a''', second: 'self_.attr[''first''] + ''b'''}
result_graphs: {}
)";

TEST(GraphDeriveScope, OldIsTheElementBeforeTheStepAndSelfSeesEarlierKeys) {
    // `is` is not in the language: the file uses == None instead (below); this checks `old` and `self_`.
    std::string yaml = kScope;
    yaml.replace(yaml.find("'old is None'"), 13, "'old == None'");
    const Derived d = derive(yaml);
    ASSERT_EQ(d.result.steps, 1);
    EXPECT_EQ(d.text(0, "n"), "6");        // old n (5) + 1
    EXPECT_EQ(d.text(0, "twice"), "12");   // self_ already has the new n
    EXPECT_EQ(d.text(1, "was_none"), "True");
    EXPECT_EQ(d.text(1, "second"), "ab");  // self_ of a new element, earlier key
}

TEST(GraphDeriveScope, VariablesPerRunAndPerApplicationAndAllRequirements) {
    std::string yaml = kScope;
    yaml.replace(yaml.find("'old is None'"), 13, "'old == None'");
    const Derived d = derive(yaml);
    EXPECT_EQ(d.text(1, "saw_run"), "101");  // global base + 1, once per derivation
    EXPECT_EQ(d.text(1, "saw_app"), "51");   // host n (5) * 10 + 1, before the step changed n
    // A requirement names the host element itself, as the original's objects do: the kept vertex
    // was updated (n = 6) by the daughter vertex before this one.
    EXPECT_EQ(d.text(1, "saw_all"), "6");
}

TEST(GraphDeriveScope, NewXAndNewYSetOneCoordinateOfANewVertex) {
    std::string yaml = kScope;
    yaml.replace(yaml.find("'old is None'"), 13, "'old == None'");
    const Derived d = derive(yaml);
    EXPECT_DOUBLE_EQ(d.result.graph.vertex(1).position.x, 7.5);
    EXPECT_DOUBLE_EQ(d.result.graph.vertex(1).position.y, 1.0);  // P.y - 1, P the host vertex at y 2
}

TEST(GraphDeriveScope, AnUnknownOperatorIsACompileErrorNamingThePlace) {
    try {
        derive(kScope);  // `old is None`: `is` is not in the whitelisted language
        FAIL() << "expected an error";
    } catch (const shapevo::InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("scope.yml:"), std::string::npos) << m;
        EXPECT_NE(m.find("production 'p'"), std::string::npos) << m;
        EXPECT_NE(m.find("was_none"), std::string::npos) << m;
    }
}

// A mother edge whose second end is an editor helper: it matches both host edges at vertex 2,
// whatever their other end (one of them even dangles), and the step marks the matched edge.
const char* kDangling = R"(
host_graphs:
  H:
    id: 1
    vertices:
    - {id: 2, attr: {x: 0, y: 0, hub: 1}}
    - {id: 3, attr: {x: 1, y: 0}}
    edges:
    - {id: 4, vertex1: 2, vertex2: 3, attr: {done: 0}}
    - {id: 5, vertex1: 2, vertex2: null, attr: {done: 0}}
productions:
  mark:
    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0, hub: 'attr == 1'}}
      - {id: 13, attr: {x: 1, y: 0, .helper_node: true}}
      edges:
      - {id: 14, vertex1: 12, vertex2: 13, attr: {done: 'attr == 0'}}
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {12: 23, 14: 25}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 0, y: 0}}
        - {id: 24, attr: {x: 1, y: 0, .helper_node: true}}
        edges:
        - {id: 25, vertex1: 23, vertex2: 24, attr: {done: 1}}
result_graphs: {}
)";

TEST(GraphDeriveScope, AMotherEdgeWithAHelperEndMatchesEdgesWhateverTheirOtherEnd) {
    const Derived d = derive(kDangling);
    EXPECT_EQ(d.result.steps, 2);  // both edges, then nothing applies
    EXPECT_EQ(d.result.graph.liveVertices(), 2u);
    EXPECT_EQ(d.result.graph.liveEdges(), 2u);
    const AttrKey done = d.grammar.names.find("done");
    for (const HostEdge& e : d.result.graph.edges()) EXPECT_EQ(toText(*e.attrs.find(done)), "1");
    // The kept edges keep their other ends: the daughter's helper end does not move them.
    EXPECT_EQ(d.result.graph.edge(0).vertex2, 1u);
    EXPECT_EQ(d.result.graph.edge(1).vertex2, kNoVertex);
}

}  // namespace derive_scope_test
