// The migration policy both rings follow (search/migration_policy.hpp): the best emigrate (ties:
// the lower slot first), the worst are replaced (ties: the higher slot first), within the slot
// range asked for; selecting one agrees with selecting many.
#include <gtest/gtest.h>

#include <vector>

#include "genome/random.hpp"
#include "search/migration_policy.hpp"

namespace shapevo {
namespace {

using Slots = std::vector<std::size_t>;

TEST(MigrationPolicy, EmigrantsAreTheBestFirstAndTheLowerSlotAmongEquals) {
    const std::vector<double> f = {0.5, 0.9, 0.2, 0.9, 0.5, 0.1};
    Slots out;
    selectEmigrants(f, 0, f.size(), 3, out);
    EXPECT_EQ(out, (Slots{1, 3, 0}));
    selectEmigrants(f, 2, 5, 2, out);  // a range: slots 2 .. 4 only
    EXPECT_EQ(out, (Slots{3, 4}));
    selectEmigrants(f, 4, 6, 5, out);  // more asked for than the range holds
    EXPECT_EQ(out, (Slots{4, 5}));
    EXPECT_EQ(bestEmigrant(f, 0, f.size()), 1u);
    EXPECT_EQ(bestEmigrant(f, 2, 5), 3u);
}

TEST(MigrationPolicy, ReplacedAreTheWorstFirstAndTheHigherSlotAmongEquals) {
    const std::vector<double> f = {0.5, 0.1, 0.2, 0.1, 0.5, 0.9};
    Slots out;
    selectReplaced(f, 0, f.size(), 3, out);
    EXPECT_EQ(out, (Slots{3, 1, 2}));
    selectReplaced(f, 0, 3, 2, out);
    EXPECT_EQ(out, (Slots{1, 2}));
    selectReplaced(f, 0, f.size(), 0, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(worstReplaced(f, 0, f.size()), 3u);
    EXPECT_EQ(worstReplaced(f, 4, 6), 4u);
    const std::vector<double> equal(4, 0.3);
    EXPECT_EQ(worstReplaced(equal, 0, 4), 3u);  // the elite, at the early slots, stays
    EXPECT_EQ(bestEmigrant(equal, 0, 4), 0u);
}

TEST(MigrationPolicy, SelectingOneIsTheFirstOfSelectingManyOnRandomFitnessWithTies) {
    Rng rng(38);
    Slots many;
    for (int n = 0; n < 500; ++n) {
        std::vector<double> f(1 + rng.below(12));
        for (double& x : f) x = double(rng.below(4)) * 0.25;  // few values: many ties
        const std::size_t first = rng.below(std::uint32_t(f.size())), last = first + 1 + rng.below(std::uint32_t(f.size() - first));
        selectEmigrants(f, first, last, last - first, many);
        ASSERT_EQ(many.size(), last - first);
        EXPECT_EQ(bestEmigrant(f, first, last), many[0]);
        for (std::size_t k = 1; k < many.size(); ++k)
            EXPECT_TRUE(f[many[k - 1]] > f[many[k]] || (f[many[k - 1]] == f[many[k]] && many[k - 1] < many[k]));
        selectReplaced(f, first, last, last - first, many);
        EXPECT_EQ(worstReplaced(f, first, last), many[0]);
        for (std::size_t k = 1; k < many.size(); ++k)
            EXPECT_TRUE(f[many[k - 1]] < f[many[k]] || (f[many[k - 1]] == f[many[k]] && many[k - 1] > many[k]));
    }
}

TEST(MigrationPolicy, ArrivalsReplaceTheWorstInOrderAndExtraArrivalsAreDropped) {
    Population p;
    for (std::uint32_t i = 0; i < 4; ++i) {
        Chromosome c;
        c.words = {i};
        c.genes = 1;
        p.individuals.push_back(c);
    }
    p.fitness = {0.4, 0.1, 0.3, 0.1};
    std::vector<Chromosome> arrivals(3, p.individuals[0]);
    for (std::uint32_t k = 0; k < 3; ++k) arrivals[k].words = {100 + k};
    replaceWorst(p, arrivals, {0.8, 0.7, 0.6}, 2);  // slots 0 and 1 open: two of the three join
    EXPECT_EQ(p.individuals[1].words, (std::vector<std::uint32_t>{100}));
    EXPECT_EQ(p.individuals[0].words, (std::vector<std::uint32_t>{101}));
    EXPECT_EQ(p.fitness, (std::vector<double>{0.7, 0.8, 0.3, 0.1}));
    EXPECT_EQ(bestIndices(p, 2), (Slots{1, 0}));
}

}  // namespace
}  // namespace shapevo
