// Genetic algorithm: with elitism the best fitness never drops, every individual stays a valid
// derivation within the length limit, and the population improves on the reachable target.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "spaceship_fixture.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/volume/volume_scorer.hpp"
#include "search/genetic_algorithm.hpp"

namespace shapevo {
namespace {

using Fixture = test::SpaceshipFixture;

TEST(GeneticAlgorithm, EliteKeepsTheBestAndEveryChildIsValid) {
    Fixture fx;
    PopulationSettings sizes;
    sizes.population = 40;
    GaSettings s;
    s.elitism = 4;
    s.tournament = 5;
    const GenomeLimits limits{60};
    Evaluator evaluator(fx.scorer, 1);
    GeneticAlgorithm ga(fx.family, sizes, s, limits, 7);
    ga.initialize(evaluator);
    double best = ga.stats().best;
    const double first = best;
    for (int gen = 0; gen < 15; ++gen) {
        ga.step(evaluator);
        EXPECT_GE(ga.stats().best, best);
        best = ga.stats().best;
        for (const Chromosome& c : ga.population().individuals) ASSERT_EQ(validateChromosome(fx.grammar, c, limits), "");
    }
    EXPECT_GT(best, first);
    EXPECT_EQ(ga.evaluations(), 40u + 15u * 36u);
}

TEST(GeneticAlgorithm, MutationOnlyAndCrossoverOnlyBothWork) {
    Fixture fx;
    for (double mutation : {0.0, 1.0}) {
        PopulationSettings sizes;
        sizes.population = 20;
        GaSettings s;
        s.elitism = 2;
        s.mutation = mutation;
        s.tournament = 3;
        const GenomeLimits limits{50};
        Evaluator evaluator(fx.scorer, 2);
        GeneticAlgorithm ga(fx.family, sizes, s, limits, 3);
        ga.initialize(evaluator);
        for (int gen = 0; gen < 5; ++gen) ga.step(evaluator);
        for (const Chromosome& c : ga.population().individuals) EXPECT_EQ(validateChromosome(fx.grammar, c, limits), "");
    }
}

TEST(GeneticAlgorithm, InitialLengthsFollowTheConfiguredRange) {
    Fixture fx;
    PopulationSettings sizes;
    sizes.population = 100;
    sizes.initialGenesMin = 10;
    sizes.initialGenesMax = 20;
    GaSettings s;
    s.elitism = 0;
    Evaluator evaluator(fx.scorer, 1);
    GeneticAlgorithm ga(fx.family, sizes, s, GenomeLimits{100}, 5);
    ga.initialize(evaluator);
    for (const Chromosome& c : ga.population().individuals) {
        EXPECT_GE(c.genes, 10u);
        EXPECT_LE(c.genes, 21u);  // a grow step may bring one mandatory child more than asked
    }
}

}  // namespace
}  // namespace shapevo
