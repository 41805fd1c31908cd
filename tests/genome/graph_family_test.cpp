// The graph-derivation family (genome/families/graph_family.hpp) on every shipped graph grammar:
// every operator's output is a valid genome that derives without error within the limits, the
// same genome always derives the same graph, an operator changes what it says it changes, and a
// parent's record from scoring and one derived by the operator give the same children.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "genome/families/graph_family.hpp"
#include "graph/read_graph_grammar.hpp"

namespace graph_family_test {

using namespace shapevo;

graph::GraphGrammar shippedGraph(const std::string& name) {
    return graph::readGraphGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/graph/" + name);
}

graph::DeriveLimits limitsFor(const graph::GraphGrammar& g) {
    graph::DeriveLimits l;
    if (g.globalLimit == 0) l.maxSteps = 1000;  // as `sample` does for a file with no limit
    return l;
}

/// Every live element's key with its position or ends, and its attributes' count.
std::map<std::uint64_t, std::vector<double>> shapeOf(const graph::HostGraph& g) {
    std::map<std::uint64_t, std::vector<double>> out;
    for (const graph::HostVertex& v : g.vertices())
        if (v.alive) out[v.key] = {v.position.x, v.position.y, double(v.attrs.entries.size())};
    for (const graph::HostEdge& e : g.edges())
        if (e.alive) out[e.key] = {double(e.vertex1), double(e.vertex2), double(e.attrs.entries.size())};
    return out;
}

/// `sequences` random operator sequences of `length` each, over a small population whose
/// members carry their records as scoring would leave them.
void runOperatorSequences(const std::string& file, int sequences, int length) {
    const graph::GraphGrammar g = shippedGraph(file);
    const GraphFamily family(g, limitsFor(g));
    GenomeLimits limits;
    limits.maxGenes = 40;
    auto ops = family.makeOperators(limits);
    Rng rng(12345);
    std::vector<Chromosome> pop(6);
    auto score = [&](Chromosome& c) {  // what the evaluator does: derive, keep the record in the lineage
        auto rec = std::make_shared<GraphDerivationRecord>();
        ASSERT_NO_THROW(family.derive(c, &rec->record)) << file;
        c.lineage = Lineage{rec};
    };
    for (Chromosome& c : pop) {
        ops->randomGenome(c, rng, 1, 1);
        score(c);
    }
    for (int s = 0; s < sequences; ++s) {
        for (int k = 0; k < length; ++k) {
            Chromosome& a = pop[rng.below(6)];
            Chromosome& b = pop[rng.below(6)];
            Chromosome x = a, y;
            switch (rng.below(7)) {
            case 0: ops->grow(x, rng); break;
            case 1: ops->cut(x, rng); break;
            case 2: ops->alter(x, rng); break;
            case 3: ops->nudge(x, rng); break;
            case 4: if (ops->regrow(a, y, rng)) x = y; break;
            case 5: ops->crossover(a, b, x, y, rng, 3); break;
            default: ops->randomGenome(x, rng, 1, 1); break;
            }
            ASSERT_EQ(family.check(x, limits), "") << file;
            score(x);
            if (s % 50 == 0 && k == 0)  // one genome, one graph
                EXPECT_EQ(shapeOf(family.derive(x).graph), shapeOf(family.derive(x).graph)) << file;
            pop[rng.below(6)] = std::move(x);
        }
    }
}

class EveryShippedGraphGrammar : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryShippedGraphGrammar, OperatorSequencesGiveValidGenomesThatDeriveWithinTheLimits) { runOperatorSequences(GetParam(), 100, 4); }

INSTANTIATE_TEST_SUITE_P(GraphFamily, EveryShippedGraphGrammar,
                         ::testing::Values("koch.yml", "tree.yml", "radial.yml", "tiled.yml", "facade.yml", "mosaic.yml"));

class EveryShippedGraphGrammarSlow : public ::testing::TestWithParam<const char*> {};

// The bound: 10,000 operator sequences per shipped graph grammar (labelled slow).
TEST_P(EveryShippedGraphGrammarSlow, TenThousandOperatorSequencesGiveValidGenomes) { runOperatorSequences(GetParam(), 10000, 2); }

INSTANTIATE_TEST_SUITE_P(GraphFamily, EveryShippedGraphGrammarSlow,
                         ::testing::Values("koch.yml", "tree.yml", "radial.yml", "tiled.yml", "facade.yml", "mosaic.yml"));

TEST(GraphFamily, ARecordFromScoringAndOneDerivedByTheOperatorGiveTheSameChildren) {
    const graph::GraphGrammar g = shippedGraph("tree.yml");
    const GraphFamily family(g, limitsFor(g));
    GenomeLimits limits;
    auto ops = family.makeOperators(limits);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Chromosome withRecord, without;
        makeGraphGenome(withRecord, seed);
        auto rec = std::make_shared<GraphDerivationRecord>();
        family.derive(withRecord, &rec->record);
        withRecord.lineage = Lineage{rec};
        makeGraphGenome(without, seed);
        Rng r1(seed), r2(seed);
        Chromosome y1, y2;
        ASSERT_TRUE(ops->regrow(withRecord, y1, r1));
        ASSERT_TRUE(ops->regrow(without, y2, r2));
        EXPECT_EQ(y1, y2);
        ASSERT_TRUE(ops->grow(y1, r1));
        ASSERT_TRUE(ops->grow(y2, r2));
        EXPECT_EQ(y1, y2);
    }
}

TEST(GraphFamily, RegrowChangesTheDrawingAndCutUndoesAnOverride) {
    const graph::GraphGrammar g = shippedGraph("tree.yml");
    const GraphFamily family(g, limitsFor(g));
    GenomeLimits limits;
    auto ops = family.makeOperators(limits);
    Rng rng(5);
    Chromosome x, y;
    makeGraphGenome(x, 77);
    const auto before = shapeOf(family.derive(x).graph);
    ASSERT_TRUE(ops->regrow(x, y, rng));
    EXPECT_EQ(y.genes, 2u);
    EXPECT_NE(shapeOf(family.derive(y).graph), before);
    ASSERT_TRUE(ops->cut(y, rng));
    EXPECT_EQ(y.genes, 1u);
    EXPECT_EQ(shapeOf(family.derive(y).graph), before);
}

TEST(GraphFamily, CheckRefusesWordsThatAreNotAGraphGenome) {
    const graph::GraphGrammar g = shippedGraph("koch.yml");
    const GraphFamily family(g, limitsFor(g));
    GenomeLimits limits;
    limits.maxGenes = 3;
    Chromosome c;
    makeGraphGenome(c, 1);
    EXPECT_EQ(family.check(c, limits), "");
    Chromosome bad = c;
    bad.words[0] = 7;
    EXPECT_NE(family.check(bad, limits).find("tag"), std::string::npos);
    bad = c;
    bad.words.push_back(1);
    EXPECT_NE(family.check(bad, limits).find("3 + 4 per override"), std::string::npos);
    setGraphOverride(c, 9, 1);
    setGraphOverride(c, 5, 1);
    EXPECT_EQ(family.check(c, limits), "");
    std::swap(c.words[3], c.words[7]);  // keys out of order
    EXPECT_NE(family.check(c, limits).find("ascend"), std::string::npos);
    setGraphOverride(c, 11, 1);
    setGraphOverride(c, 12, 1);
    EXPECT_NE(family.check(c, limits).find("max_genes"), std::string::npos);
}

}  // namespace graph_family_test
