// Migrants from other ranks replace the worst individuals of the slots a search method opens to
// them (SearchMethod::migrantSlots): the hybrid's scout island, the last slots, never receives one.
#include <gtest/gtest.h>

#include "island/ring_migration.hpp"

namespace shapevo {
namespace {

Chromosome marked(std::uint32_t mark) {
    Chromosome c;
    c.words = {mark};
    c.genes = 1;
    return c;
}

Population sixIndividuals() {
    Population p;
    const double fitness[] = {0.9, 0.2, 0.5, 0.2, 0.0, 0.1};  // slots 4 and 5: the worst, a scout's
    for (std::uint32_t i = 0; i < 6; ++i) {
        p.individuals.push_back(marked(i));
        p.fitness.push_back(fitness[i]);
    }
    return p;
}

TEST(ReplaceWorst, ArrivalsReplaceTheWorstOfTheOpenSlotsOnly) {
    Population p = sixIndividuals();
    replaceWorst(p, {marked(100), marked(101)}, {0.7, 0.6}, 4);
    // Among slots 0-3 the worst are the two 0.2s, the later first; slots 4 and 5 are untouched.
    EXPECT_EQ(p.individuals[3], marked(100));
    EXPECT_EQ(p.fitness[3], 0.7);
    EXPECT_EQ(p.individuals[1], marked(101));
    EXPECT_EQ(p.fitness[1], 0.6);
    EXPECT_EQ(p.individuals[4], marked(4));
    EXPECT_EQ(p.individuals[5], marked(5));
}

TEST(ReplaceWorst, AllSlotsOpenReplacesTheWorstOfThePopulation) {
    Population p = sixIndividuals();
    replaceWorst(p, {marked(100), marked(101)}, {0.7, 0.6}, p.size());
    EXPECT_EQ(p.individuals[4], marked(100));
    EXPECT_EQ(p.individuals[5], marked(101));
    EXPECT_EQ(p.individuals[1], marked(1));
}

}  // namespace
}  // namespace shapevo
