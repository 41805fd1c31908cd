// The SearchMethod implementations: SMC particles start empty and gain one geometric object per
// generation, resampling follows the incremental weights, the factory builds what the settings
// name, and every method resumed from (population, RNG, generation, evaluations) continues
// exactly as the uninterrupted run.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "spaceship_fixture.hpp"
#include "function_scorer.hpp"
#include "genome/sequential_growth.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/volume/volume_scorer.hpp"
#include "search/rjmcmc.hpp"
#include "search/search_methods.hpp"
#include "search/smc.hpp"

namespace shapevo {
namespace {

const char* kFan = R"(
start R
rule R { box child Y prob 0.5 max 6 }
rule Y { param k = choice(0, 1) box }
)";

/// Number of Y genes with k = 1.
double onesOf(const Grammar& g, const Chromosome& x) {
    double n = 0;
    for (std::uint32_t pos = 0; pos < x.size(); pos += g.rules[x.rule(pos)].geneWords())
        if (x.rule(pos) == 1) n += x.param(pos, g.rules[1], 0);
    return n;
}

TEST(Smc, ParticlesStartEmptyAndGainOneObjectPerGeneration) {
    const Grammar g = parseGrammar(kFan, "fan.grammar");
    test::FunctionScorer scorer(g, [&](const Chromosome& x) { return onesOf(g, x); });
    Evaluator evaluator(scorer, 2);
    SmcSettings s;
    s.temperature = 1e9;  // weights all but equal: pure growth
    Smc smc(g, s, 40, GenomeLimits{20}, GrowthOrder::Chromosome, 1);
    smc.initialize(evaluator);
    EXPECT_EQ(smc.generation(), 1u);
    EXPECT_EQ(smc.evaluations(), 40u);
    for (const Chromosome& c : smc.population().individuals) EXPECT_EQ(c.genes, 1u) << "the root is the first object";
    std::uint64_t before = smc.evaluations();
    for (std::uint32_t gen = 2; gen <= 12; ++gen) {
        smc.step(evaluator);
        for (const Chromosome& c : smc.population().individuals) {
            EXPECT_LE(c.genes, gen) << "every gene of this grammar is a box: at most one per generation";
            ASSERT_EQ(validateChromosome(g, c, GenomeLimits{20}), "");
        }
        EXPECT_LE(smc.evaluations() - before, 40u) << "at most one evaluation per particle and generation";
        before = smc.evaluations();
    }
    for (const Chromosome& c : smc.population().individuals) EXPECT_EQ(undecidedChildren(g, c), 0u);
    const std::uint64_t done = smc.evaluations();
    smc.step(evaluator);
    EXPECT_EQ(smc.evaluations(), done) << "complete particles are not evaluated again";
}

TEST(Smc, ResamplingFollowsTheIncrementalWeight) {
    const Grammar g = parseGrammar(kFan, "fan.grammar");
    test::FunctionScorer scorer(g, [&](const Chromosome& x) { return onesOf(g, x); });
    Evaluator evaluator(scorer, 1);
    SmcSettings s;
    s.temperature = 0.01;  // a gain of 1 weighs e^100 times more
    Smc smc(g, s, 50, GenomeLimits{20}, GrowthOrder::Random, 3);
    smc.initialize(evaluator);
    smc.step(evaluator);  // one Y each (or none): those with k = 1 take every slot
    for (double f : smc.population().fitness) EXPECT_EQ(f, 1.0);
    smc.step(evaluator);
    for (double f : smc.population().fitness) EXPECT_EQ(f, 2.0);
}

/// Run `method` for `total` generations, or `split` then a restored copy for the rest.
template <class Make>
void expectResumeEqualsUninterrupted(Make make, Evaluator& evaluator, std::uint32_t split, std::uint32_t total) {
    auto whole = make();
    whole->initialize(evaluator);
    while (whole->generation() < total) whole->step(evaluator);
    auto first = make();
    first->initialize(evaluator);
    while (first->generation() < split) first->step(evaluator);
    auto second = make();
    second->restore(first->population(), first->rng().state(), first->generation(), first->evaluations());
    while (second->generation() < total) second->step(evaluator);
    EXPECT_EQ(second->evaluations(), whole->evaluations());
    EXPECT_EQ(second->rng().state(), whole->rng().state());
    ASSERT_EQ(second->population().size(), whole->population().size());
    for (std::size_t i = 0; i < whole->population().size(); ++i) {
        EXPECT_EQ(second->population().individuals[i], whole->population().individuals[i]) << i;
        EXPECT_EQ(second->population().fitness[i], whole->population().fitness[i]) << i;
    }
}

using Spaceship = test::SpaceshipFixture;

TEST(SearchMethods, EveryMethodResumedFromItsSavedStateEqualsTheUninterruptedRun) {
    Spaceship fx;
    Evaluator evaluator(fx.scorer, 2);
    PopulationSettings sizes;
    sizes.population = 24;
    GaSettings ga;
    ga.elitism = 4;
    ga.tournament = 4;
    const GenomeLimits limits{60};
    for (const SearchMethodEntry& method : searchMethods()) {
        SearchSettings s;
        s.method = method.name;
        s.rjmcmc.delayedRejection = true;
        s.rjmcmc.annealingInterval = 2;
        s.hybrid.migrationInterval = 3;  // the hybrid migrates and restarts on both sides of the split
        s.hybrid.restartInterval = 4;
        s.hybrid.scoutInterval = 3;  // and its scout is adopted or starts again on both sides
        expectResumeEqualsUninterrupted([&] { return makeSearchMethod(s, sizes, ga, fx.family, limits, 77, "test.toml"); }, evaluator, 5, 11);
    }
}

TEST(SearchMethods, FactoryBuildsTheNamedMethodAndEveryOneImproves) {
    Spaceship fx;
    Evaluator evaluator(fx.scorer, 2);
    PopulationSettings sizes;
    sizes.population = 30;
    GaSettings ga;
    ga.elitism = 4;
    const GenomeLimits limits{60};
    for (const SearchMethodEntry& method : searchMethods()) {
        if (method.name == "ga") continue;  // the GA's own tests are in genetic_algorithm_test.cpp
        SearchSettings s;
        s.method = method.name;
        SCOPED_TRACE(std::string(method.name));
        auto m = makeSearchMethod(s, sizes, ga, fx.family, limits, 5, "test.toml");
        m->initialize(evaluator);
        const double first = m->stats().best;
        while (m->generation() < 25) m->step(evaluator);
        EXPECT_GT(m->stats().best, first);
        if (method.name == "hybrid")  // its children, plus refine x population local moves, plus restarts
            EXPECT_LE(m->evaluations(), 25u * 30u * (1 + s.hybrid.refine) + 30u);
        else
            EXPECT_LE(m->evaluations(), 25u * 30u) << "at most one evaluation per individual and generation";
        if (method.name == "rjmcmc") {
            EXPECT_GE(m->evaluations(), 25u * 30u * 3 / 4);
        }
        for (const Chromosome& c : m->population().individuals) ASSERT_EQ(validateChromosome(fx.grammar, c, limits), "");
    }
}

}  // namespace
}  // namespace shapevo
