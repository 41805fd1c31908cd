// Hybrid search: islands partition the population, each island keeps its elites and breeds only
// from its own members, refinement never makes a model worse (the best never drops, restarts
// included), migration copies each island's best into the next island, a restart regrows the
// worst island, a scout island neither sends nor receives migrants and replaces the worst island
// only when better, and the run is the same with one or two evaluation threads and after a resume.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "../test_support.hpp"
#include "spaceship_fixture.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/volume/volume_scorer.hpp"
#include "search/hybrid_search.hpp"

namespace shapevo {
namespace {

using Fixture = test::SpaceshipFixture;

PopulationSettings sized(std::uint32_t population) {
    PopulationSettings p;
    p.population = population;
    return p;
}

GaSettings smallGa() {
    GaSettings ga;
    ga.elitism = 6;
    ga.tournament = 4;
    return ga;
}

double islandBest(const HybridSearch& h, std::size_t k) {
    const auto& f = h.population().fitness;
    return *std::max_element(f.begin() + std::ptrdiff_t(h.islandBegin(k)), f.begin() + std::ptrdiff_t(h.islandBegin(k + 1)));
}

TEST(HybridSearch, IslandsSplitThePopulationEvenlyAndKeepTheirShareOfElites) {
    Fixture fx;
    HybridSettings s;
    s.islands = 4;
    HybridSearch h(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 1);
    ASSERT_EQ(h.islands(), 4u);
    std::size_t elites = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t m = h.islandBegin(k + 1) - h.islandBegin(k);
        EXPECT_TRUE(m == 7 || m == 8) << k;
        EXPECT_GE(h.islandElites(k), 1u);
        elites += h.islandElites(k);
    }
    EXPECT_EQ(h.islandBegin(0), 0u);
    EXPECT_EQ(h.islandBegin(4), 30u);
    EXPECT_EQ(elites, 6u);
    s.islands = 100;  // more islands than pairs of individuals: islands of at least two
    EXPECT_EQ(HybridSearch(fx.family, s, sized(9), smallGa(), GenomeLimits{60}, 1).islands(), 4u);
}

TEST(HybridSearch, TheBestNeverDropsAndEveryIndividualStaysValid) {
    Fixture fx;
    HybridSettings s;
    s.restartInterval = 3;  // restarts often: they replace the worst island only
    s.migrationInterval = 2;
    s.scoutInterval = 4;  // and a scout (island 3) is adopted or starts again often
    const GenomeLimits limits{60};
    Evaluator evaluator(fx.scorer, 1);
    HybridSearch h(fx.family, s, sized(40), smallGa(), limits, 7);
    h.initialize(evaluator);
    const double first = h.stats().best;
    double best = first;
    for (int gen = 0; gen < 20; ++gen) {
        h.step(evaluator);
        EXPECT_GE(h.stats().best, best) << "generation " << h.generation();
        best = h.stats().best;
        for (const Chromosome& c : h.population().individuals) ASSERT_EQ(validateChromosome(fx.grammar, c, limits), "");
    }
    EXPECT_GT(best, first);
    const OperatorOutcomes& o = *h.operatorOutcomes();
    for (int op : {OperatorOutcomes::Regrow, OperatorOutcomes::Refine, OperatorOutcomes::Crossover, OperatorOutcomes::Cut})
        EXPECT_GT(o.children[op][0] + o.children[op][1] + o.children[op][2], 0u) << OperatorOutcomes::kOpNames[op];
}

/// Two hybrids of `s` on the spaceship (30 individuals), equal up to generation 3; generation 4
/// migrates in `migrated` (every 4 generations) and not in `plain`.
struct MigrationTwins {
    Fixture fx;
    Evaluator evaluator{fx.scorer, 1};
    std::unique_ptr<HybridSearch> migrated, plain;
    explicit MigrationTwins(HybridSettings s) {
        s.migrationInterval = 4;
        s.refine = 0;  // so that the last step's breeding is all that changes the islands before migrating
        migrated = std::make_unique<HybridSearch>(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 11);
        migrated->initialize(evaluator);
        while (migrated->generation() < 3) migrated->step(evaluator);
        s.migrationInterval = 0;
        plain = std::make_unique<HybridSearch>(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 11);
        plain->restore(migrated->population(), migrated->rng().state(), 3, migrated->evaluations());
        migrated->step(evaluator);
        plain->step(evaluator);
    }
};

TEST(HybridSearch, MigrationCopiesEachIslandsBestIntoTheNextIsland) {
    HybridSettings s;
    s.islands = 3;
    s.restartInterval = 0;
    s.scoutInterval = 0;  // three islands in the ring
    const MigrationTwins t(s);
    const HybridSearch &h = *t.migrated, &twin = *t.plain;
    ASSERT_EQ(h.generation(), 4u);
    // Generation 4 migrates: island k + 1's worst is now island k's best; nothing else changed.
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t next = (k + 1) % 3;
        EXPECT_EQ(islandBest(h, next), std::max(islandBest(twin, next), islandBest(twin, k))) << k << " -> " << next;
        std::size_t changed = 0;
        for (std::size_t i = h.islandBegin(next); i < h.islandBegin(next + 1); ++i)
            changed += !(h.population().individuals[i] == twin.population().individuals[i]);
        EXPECT_LE(changed, 1u) << "one migrant per island";
    }
}

TEST(HybridSearch, ARestartRegrowsTheWorstIslandOnly) {
    Fixture fx;
    HybridSettings s;
    s.islands = 2;
    s.migrationInterval = 0;
    s.restartInterval = 5;
    Evaluator evaluator(fx.scorer, 1);
    HybridSearch h(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 5);
    h.initialize(evaluator);
    while (h.generation() < 4) h.step(evaluator);
    const Population before = h.population();
    const std::uint64_t evaluations = h.evaluations();
    s.restartInterval = 0;  // the same generation 5 without the restart
    HybridSearch noRestart(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 5);
    noRestart.restore(before, h.rng().state(), 4, evaluations);
    h.step(evaluator);
    noRestart.step(evaluator);
    const std::size_t worst = islandBest(noRestart, 0) <= islandBest(noRestart, 1) ? 0 : 1;
    // the restart evaluates one island more; the other island is what the plain step made
    EXPECT_EQ(h.evaluations(), noRestart.evaluations() + (h.islandBegin(worst + 1) - h.islandBegin(worst)));
    std::size_t same = 0;
    for (std::size_t i = 0; i < 30; ++i) {
        const bool inWorst = i >= h.islandBegin(worst) && i < h.islandBegin(worst + 1);
        if (!inWorst) {
            EXPECT_EQ(h.population().individuals[i], noRestart.population().individuals[i]) << i;
        } else {
            same += h.population().individuals[i] == noRestart.population().individuals[i];
        }
    }
    EXPECT_LE(same, 1u) << "the worst island starts again from random growth";
}

TEST(HybridSearch, AScoutIslandNeitherSendsNorReceivesMigrants) {
    HybridSettings s;
    s.islands = 3;
    s.restartInterval = 0;
    s.scoutInterval = 1000;  // a scout (island 2) whose turn does not come in this test
    const MigrationTwins t(s);
    const HybridSearch &h = *t.migrated, &twin = *t.plain;
    ASSERT_EQ(h.generation(), 4u);
    // Islands 0 and 1 swap their best; the scout, island 2, is what breeding made of it.
    for (std::size_t i = h.islandBegin(2); i < 30; ++i)
        EXPECT_EQ(h.population().individuals[i], twin.population().individuals[i]) << i;
    EXPECT_EQ(islandBest(h, 1), std::max(islandBest(twin, 1), islandBest(twin, 0)));
    EXPECT_EQ(islandBest(h, 0), std::max(islandBest(twin, 0), islandBest(twin, 1)));
}

TEST(HybridSearch, MigrantsFromOtherRanksMayLandInTheMainIslandsOnly) {
    Fixture fx;
    HybridSettings s;
    s.islands = 3;
    EXPECT_EQ(HybridSearch(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 1).migrantSlots(), 20u);
    s.scoutInterval = 0;  // no scout: every slot
    EXPECT_EQ(HybridSearch(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 1).migrantSlots(), 30u);
    s.islands = 2;
    s.scoutInterval = 400;  // two islands keep no scout
    EXPECT_EQ(HybridSearch(fx.family, s, sized(30), smallGa(), GenomeLimits{60}, 1).migrantSlots(), 30u);
}

TEST(HybridSearch, ABetterScoutReplacesTheWorstIslandAndStartsAgain) {
    Fixture fx;
    HybridSettings s;
    s.islands = 3;
    s.migrationInterval = 0;
    s.restartInterval = 0;
    s.scoutInterval = 5;
    Evaluator evaluator(fx.scorer, 1);
    for (const bool better : {true, false}) {
        HybridSearch h(fx.family, s, sized(32), smallGa(), GenomeLimits{60}, 5);
        h.initialize(evaluator);
        while (h.generation() < 4) h.step(evaluator);
        // The scout's members made (or not) better than every other model, as if it had found
        // a better basin: elites keep their fitness, so the scout's best stays best.
        Population p = h.population();
        for (std::size_t i = h.islandBegin(2); i < 32; ++i) p.fitness[i] += better ? 1000.0 : -1000.0;
        h.restore(p, h.rng().state(), 4, h.evaluations());
        HybridSettings plain = s;
        plain.scoutInterval = 0;  // three equal islands; nothing happens at generation 5
        HybridSearch twin(fx.family, plain, sized(32), smallGa(), GenomeLimits{60}, 5);
        twin.restore(p, h.rng().state(), 4, h.evaluations());
        h.step(evaluator);
        twin.step(evaluator);
        const std::size_t worst = islandBest(twin, 0) <= islandBest(twin, 1) ? 0 : 1, other = 1 - worst;
        const std::size_t scoutSize = 32 - h.islandBegin(2);
        EXPECT_EQ(h.evaluations(), twin.evaluations() + scoutSize) << "the scout starts again";
        for (std::size_t i = h.islandBegin(other); i < h.islandBegin(other + 1); ++i)
            EXPECT_EQ(h.population().individuals[i], twin.population().individuals[i]) << i;
        std::size_t same = 0;
        for (std::size_t i = h.islandBegin(2); i < 32; ++i) same += h.population().individuals[i] == twin.population().individuals[i];
        EXPECT_LE(same, 1u) << "the scout regrows from random growth";
        const bool adopted = islandBest(twin, 2) > islandBest(twin, worst);
        if (better) EXPECT_TRUE(adopted);
        if (adopted) {
            // The worst island now holds the scout's members, best first; its best is the scout's.
            EXPECT_EQ(islandBest(h, worst), islandBest(twin, 2));
            std::vector<double> scout(twin.population().fitness.begin() + std::ptrdiff_t(h.islandBegin(2)),
                                      twin.population().fitness.end());
            std::sort(scout.rbegin(), scout.rend());
            for (std::size_t i = h.islandBegin(worst), j = 0; i < h.islandBegin(worst + 1); ++i, ++j)
                EXPECT_EQ(h.population().fitness[i], scout[j < scout.size() ? j : 0]) << i;
        } else {
            for (std::size_t i = h.islandBegin(worst); i < h.islandBegin(worst + 1); ++i)
                EXPECT_EQ(h.population().individuals[i], twin.population().individuals[i]) << i;
        }
    }
}

/// The population after `generations` steps of a hybrid run on the spaceship.
Population hybridRun(const HybridSettings& s, std::uint32_t population, int generations) {
    Fixture fx;
    Evaluator ev(fx.scorer, 1);
    HybridSearch h(fx.family, s, sized(population), smallGa(), GenomeLimits{60}, 7);
    h.initialize(ev);
    for (int gen = 0; gen < generations; ++gen) h.step(ev);
    return h.population();
}

TEST(HybridSearch, NudgesRefineTheOddIslandsOnlyAndAltersTheEvenOnes) {
    HybridSettings s;
    s.refine = 1.0;
    s.refineJump = 0.0;  // every local move is an alter or a nudge
    for (std::uint32_t islands : {1u, 2u}) {
        s.islands = islands;
        s.refineNudge = 0.0;
        const Population alters = hybridRun(s, 24, 8);
        s.refineNudge = 1.0;
        const Population nudges = hybridRun(s, 24, 8);
        const bool same = alters.individuals == nudges.individuals && alters.fitness == nudges.fitness;
        // One island (island 0, even): the key changes nothing. Two: island 1 nudges.
        EXPECT_EQ(same, islands == 1) << islands << " islands";
    }
}

TEST(HybridSearch, OneAndTwoThreadsGiveTheSameRun) {
    Fixture fx;
    HybridSettings s;
    s.restartInterval = 4;
    s.migrationInterval = 3;
    s.scoutInterval = 5;
    Evaluator one(fx.scorer, 1), two(fx.scorer, 2);
    HybridSearch a(fx.family, s, sized(40), smallGa(), GenomeLimits{60}, 3), b(fx.family, s, sized(40), smallGa(), GenomeLimits{60}, 3);
    a.initialize(one);
    b.initialize(two);
    for (int gen = 0; gen < 12; ++gen) {
        a.step(one);
        b.step(two);
    }
    EXPECT_EQ(a.evaluations(), b.evaluations());
    EXPECT_EQ(a.rng().state(), b.rng().state());
    for (std::size_t i = 0; i < 40; ++i) {
        EXPECT_EQ(a.population().individuals[i], b.population().individuals[i]) << i;
        EXPECT_EQ(a.population().fitness[i], b.population().fitness[i]) << i;
    }
}

}  // namespace
}  // namespace shapevo
