// Keyed derivations (graph/keyed_draws.hpp, derive.hpp's firing levels): the shipped grammars
// keep their structure; one seed and one set of overrides give one graph; the choice of event has
// the sequential derivation's law (a uniform applicable production, then a uniform match, at every
// step); and an override of one event's seed changes only that event's descendants.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "graph/derive.hpp"
#include "graph/keyed_draws.hpp"
#include "graph/read_graph_grammar.hpp"

namespace keyed_derivation_test {

using namespace shapevo::graph;

GraphGrammar shipped(const std::string& name) {
    return readGraphGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/graph/" + name);
}

DeriveResult deriveKeyed(const GraphGrammar& g, std::uint64_t seed, const std::vector<std::uint32_t>& overrides = {},
                         DecisionRecord* record = nullptr, std::int64_t steps = 0) {
    KeyedDraws draws(seed, overrides, record);
    DeriveLimits limits;
    limits.maxSteps = steps;
    return deriveGraph(g, 0, draws, limits);
}

void addOverride(std::vector<std::uint32_t>& o, std::uint64_t key, std::uint64_t word) {  // keeps keys ascending
    std::size_t i = 0;
    while (i < o.size() / kOverrideWords && overrideKey(o, i) < key) ++i;
    const std::uint32_t w[4] = {std::uint32_t(key), std::uint32_t(key >> 32), std::uint32_t(word), std::uint32_t(word >> 32)};
    o.insert(o.begin() + std::ptrdiff_t(i * kOverrideWords), w, w + 4);
}

/// Each live element by key: its position(s) (model units, rounded to 1e-9).
std::map<std::uint64_t, std::vector<long long>> elementsByKey(const HostGraph& g) {
    std::map<std::uint64_t, std::vector<long long>> out;
    auto q = [](double x) { return (long long)std::llround(x * 1e9); };
    for (const HostVertex& v : g.vertices())
        if (v.alive) out[v.key] = {q(v.position.x), q(v.position.y)};
    for (const HostEdge& e : g.edges())
        if (e.alive) out[e.key] = {(long long)e.vertex1, (long long)e.vertex2};
    return out;
}

TEST(KeyedDerivation, ShippedTreeKeepsItsStructureForEverySeed) {
    const GraphGrammar g = shipped("tree.yml");
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const DeriveResult r = deriveKeyed(g, seed);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        EXPECT_EQ(r.steps, 143) << "seed " << seed;
        EXPECT_EQ(r.graph.elements(), std::size_t(3 + 4 * r.steps));
    }
}

TEST(KeyedDerivation, ShippedKochKeepsSixElementsPerStep) {
    const GraphGrammar g = shipped("koch.yml");
    for (std::uint64_t seed = 1; seed <= 5; ++seed)
        for (std::int64_t steps : {1, 7, 64}) EXPECT_EQ(deriveKeyed(g, seed, {}, nullptr, steps).graph.elements(), std::size_t(6 + 6 * steps));
}

TEST(KeyedDerivation, OneSeedAndOneSetOfOverridesGiveOneGraph) {
    const GraphGrammar g = shipped("tree.yml");
    EXPECT_EQ(elementsByKey(deriveKeyed(g, 7).graph), elementsByKey(deriveKeyed(g, 7).graph));
    EXPECT_NE(elementsByKey(deriveKeyed(g, 7).graph), elementsByKey(deriveKeyed(g, 8).graph));
}

/// `hostVertices` free vertices in a row and one production `name` that marks a free vertex taken
/// and, with `sprout`, makes a new free vertex above it.
std::string freeVerticesGrammar(const std::string& name, int hostVertices, bool sprout) {
    std::string s = "host_graphs:\n  H:\n    id: 1\n    vertices:\n";
    for (int i = 0; i < hostVertices; ++i)
        s += "    - {id: " + std::to_string(2 + i) + ", attr: {x: " + std::to_string(i) + ", y: 0, state: free}}\n";
    s += "    edges: []\nproductions:\n  " + name + ":\n" + R"(    id: 10
    mother_graph:
      id: 11
      vertices:
      - {id: 12, attr: {x: 0, y: 0, state: "attr == 'free'"}}
      edges: []
    mappings:
    - id: 20
      mother_graph: 11
      mapping: {id: 21, dict: {12: 23}}
      daughter_graph:
        id: 22
        vertices:
        - {id: 23, attr: {x: 0, y: 0, state: "'taken'"}}
)";
    if (sprout) s += "        - {id: 24, attr: {x: 0, y: 5, state: \"'free'\"}}\n";
    return s + "        edges: []\nresult_graphs: {}\n";
}

// Four vertices labelled free; "take" marks one. Which is taken first, and second, over seeds.
const std::string kTake = freeVerticesGrammar("take", 4, false);

/// The index (0..3) of the first host vertex whose state is `taken` and not in `skip`.
int takenVertex(const GraphGrammar& g, const HostGraph& graph, const std::set<int>& skip) {
    const AttrKey state = g.names.find("state");
    for (int i = 0; i < 4; ++i) {
        const Value* v = graph.vertex(ElementId(i)).attrs.find(state);
        if (!skip.count(i) && v && v->asString() && *v->asString() == "taken") return i;
    }
    return -1;
}

TEST(KeyedDerivation, EveryStepPicksUniformlyAmongTheMatchesLikeTheSequentialDerivation) {
    const GraphGrammar g = parseGraphGrammar(kTake, "take.yml");
    const int n = 8000;
    std::map<int, int> first;
    std::map<std::pair<int, int>, int> second;
    for (int seed = 1; seed <= n; ++seed) {
        const int a = takenVertex(g, deriveKeyed(g, std::uint64_t(seed), {}, nullptr, 1).graph, {});
        const int b = takenVertex(g, deriveKeyed(g, std::uint64_t(seed), {}, nullptr, 2).graph, {a});
        ++first[a];
        ++second[{a, b}];
    }
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(first[i] / double(n), 0.25, 0.02) << "vertex " << i;
    // Memoryless: given the first, the second is uniform among the three left.
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            if (a != b) EXPECT_NEAR(second[std::make_pair(a, b)] / double(first[a]), 1.0 / 3, 0.04) << a << " then " << b;
}

// Two free vertices; "sprout" takes one and makes a new free one. The second step takes the older
// survivor or the new vertex with equal chance (firing levels of matches found later start from the
// production's clock then, so an older match is not favoured or disfavoured).
const std::string kSprout = freeVerticesGrammar("sprout", 2, true);

TEST(KeyedDerivation, AMatchFoundLaterIsAsLikelyToFireAsAnOlderOne) {
    const GraphGrammar g = parseGraphGrammar(kSprout, "sprout.yml");
    const AttrKey state = g.names.find("state");
    const int n = 8000;
    int newer = 0;
    for (int seed = 1; seed <= n; ++seed) {
        const DeriveResult r = deriveKeyed(g, std::uint64_t(seed), {}, nullptr, 2);
        // vertices 0, 1: the host's; 2: made by step 1; 3: made by step 2
        const Value* v = r.graph.vertex(2).attrs.find(state);
        newer += v && v->asString() && *v->asString() == "taken";
    }
    EXPECT_NEAR(newer / double(n), 0.5, 0.02);
}

TEST(KeyedDerivation, ASeedOverrideAtOneEventChangesOnlyItsDescendants) {
    const GraphGrammar g = shipped("tree.yml");
    DecisionRecord record;
    const DeriveResult base = deriveKeyed(g, 3, {}, &record);
    ASSERT_EQ(record.events.size(), std::size_t(base.steps) + 1);
    int checked = 0;
    for (std::uint32_t e : {20u, 60u, 100u}) {
        std::vector<std::uint32_t> o;
        addOverride(o, record.events[e].saltKey, 0x1234567887654321ULL);
        const DeriveResult changed = deriveKeyed(g, 3, o);
        // Events that descend from e (parents come before children).
        std::vector<char> below(record.events.size(), 0);
        below[e] = 1;
        for (std::size_t k = e + 1; k < record.events.size(); ++k) below[k] = below[record.events[k].parent];
        std::set<std::uint64_t> subtreeKeys;
        for (std::size_t k = 0; k < record.events.size(); ++k)
            if (below[k]) subtreeKeys.insert(record.events[k].eventKey);
        const auto before = elementsByKey(base.graph), after = elementsByKey(changed.graph);
        EXPECT_NE(before, after) << "event " << e;
        for (const HostVertex& v : base.graph.vertices()) {
            if (!v.alive || below[v.birth]) continue;
            ASSERT_TRUE(after.count(v.key)) << "event " << e;
            EXPECT_EQ(after.at(v.key), before.at(v.key)) << "event " << e;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
}

}  // namespace keyed_derivation_test
