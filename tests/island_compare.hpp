// expectSameIslands: two checkpoints hold the same islands (for the resume-equals-uninterrupted
// and repeatability tests under mpirun).
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "checkpoint/checkpoint_file.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "test_support.hpp"

namespace shapevo::test {

/// Islands of a checkpoint must match: chromosomes, fitness bits, RNG, curve (but seconds).
inline void expectSameIslands(const std::string& a, const std::string& b, int ranks) {
    const Grammar g = loadGrammar(sourcePath("grammars/spaceship.grammar"));
    const TreeFamily family(g);
    const GenomeLimits limits{100};
    for (int r = 0; r < ranks; ++r) {
        const IslandState x = readIslandFile(a + "/" + islandFileName(r), family, limits);
        const IslandState y = readIslandFile(b + "/" + islandFileName(r), family, limits);
        EXPECT_EQ(x.generation, y.generation);
        EXPECT_EQ(x.evaluations, y.evaluations);
        EXPECT_EQ(x.rng, y.rng);
        ASSERT_EQ(x.population.size(), y.population.size());
        for (std::size_t i = 0; i < x.population.size(); ++i) {
            EXPECT_EQ(x.population.individuals[i], y.population.individuals[i]) << "island " << r << " individual " << i;
            EXPECT_EQ(x.population.fitness[i], y.population.fitness[i]);
        }
        ASSERT_EQ(x.curve.size(), y.curve.size());
        for (std::size_t i = 0; i < x.curve.size(); ++i) {
            EXPECT_EQ(x.curve[i].generation, y.curve[i].generation);
            EXPECT_EQ(x.curve[i].evaluations, y.curve[i].evaluations);
            EXPECT_EQ(x.curve[i].best, y.curve[i].best);
            EXPECT_EQ(x.curve[i].mean, y.curve[i].mean);
            EXPECT_EQ(x.curve[i].std, y.curve[i].std);
        }
    }
}

}  // namespace shapevo::test
