// Search diagnostics from the search layer: population diversity counted exactly (equal genomes,
// genomes equal but for their parameters), and the GA's operator outcomes account for every child.
#include <gtest/gtest.h>

#include "genome/families/tree_family.hpp"
#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "search/genetic_algorithm.hpp"
#include "search/population_diversity.hpp"
#include "function_scorer.hpp"
#include "../small_tree_grammar.hpp"

namespace shapevo {
namespace {

TEST(PopulationDiversity, CountsEqualGenomesAndEqualStructuresExactly) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    Rng rng(4);
    const GenomeLimits limits{30};
    Chromosome a, b;
    for (; a.genes < 6 && grow(g, a, rng, limits);) {
    }
    for (; b.genes < 9 && grow(g, b, rng, limits);) {
    }
    Chromosome a2 = a;  // a's structure, other parameters
    ASSERT_TRUE(alter(g, a2, rng));
    ASSERT_NE(a2.words, a.words);
    Population pop;
    pop.individuals = {a, b, a, a2, b, a2, a};
    DiversityScratch scratch;
    const Diversity d = measureDiversity(TreeFamily(g), pop, scratch);
    EXPECT_EQ(d.distinctGenomes, 3u);     // a, b, a2
    EXPECT_EQ(d.distinctStructures, 2u);  // a = a2, b
    EXPECT_EQ(d.maxGenes, b.genes);
    EXPECT_DOUBLE_EQ(d.meanGenes, (4.0 * a.genes + 2.0 * b.genes + a2.genes) / 7.0);
}

TEST(OperatorOutcomes, EveryChildOfEveryGenerationIsCountedOnceAgainstItsParent) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    test::FunctionScorer scorer(g, [](const Chromosome& c) { return double(c.genes % 7) + 0.01 * double(c.words.size() % 5); });
    PopulationSettings sizes;
    sizes.population = 41;  // an odd number of children: the last pair's second child is discarded
    GaSettings settings;
    settings.elitism = 6;
    const TreeFamily family(g);
    GeneticAlgorithm ga(family, sizes, settings, GenomeLimits{40}, 3);
    Evaluator evaluator(scorer, 1);
    ga.initialize(evaluator);
    for (int i = 0; i < 25; ++i) ga.step(evaluator);
    const OperatorOutcomes& o = *ga.operatorOutcomes();
    std::uint64_t children = 0, better = 0, worse = 0;
    for (const auto& op : o.children) {
        for (std::uint64_t n : op) children += n;
        better += op[OperatorOutcomes::Better];
        worse += op[OperatorOutcomes::Worse];
    }
    EXPECT_EQ(children, 25u * 35u);
    EXPECT_GT(better, 0u);
    EXPECT_GT(worse, 0u);
    EXPECT_GT(o.children[OperatorOutcomes::Crossover][OperatorOutcomes::Equal] +
                  o.children[OperatorOutcomes::Crossover][OperatorOutcomes::Better] +
                  o.children[OperatorOutcomes::Crossover][OperatorOutcomes::Worse],
              0u);
    EXPECT_EQ(o.parentsPicked, 25u * 36u);
    EXPECT_LE(o.distinctParents, o.parentsPicked);
    EXPECT_GT(o.distinctParents, 25u);
}

}  // namespace
}  // namespace shapevo
