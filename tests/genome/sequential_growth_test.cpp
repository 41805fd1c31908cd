// SMC / SOSMC growth: futures are decided in chromosome order (SMC) or uniformly at random
// (SOSMC), refused futures are marked kRefused and never grown again, each call adds exactly one
// geometric object, and every result is a valid derivation.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "genome/sequential_growth.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

/// Root with a never-expressed slot, then four optional boxes.
const char* kFan = R"(
start R
rule R {
  box
  child X prob 0
  child Y prob 0.5 max 4
}
rule X { box }
rule Y { param k = choice(0, 1) box }
)";

/// True if the decided child positions of `c` form a prefix of chromosome order.
bool decidedArePrefix(const Grammar& g, const Chromosome& c) {
    bool undecidedSeen = false;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords())
        for (std::uint32_t e = 0; e < g.rules[c.rule(pos)].childOffsets; ++e) {
            if (c.child(pos, e) == kNotExpressed) undecidedSeen = true;
            else if (undecidedSeen) return false;
        }
    return true;
}

std::uint32_t geometricGenes(const Grammar& g, const Chromosome& c, const std::vector<char>& geometric) {
    std::uint32_t n = 0;
    for (std::uint32_t pos = 0; pos < c.size(); pos += g.rules[c.rule(pos)].geneWords()) n += geometric[c.rule(pos)];
    return n;
}

TEST(SequentialGrowth, SmcDecidesFuturesInChromosomeOrderAndMarksRefusals) {
    const Grammar g = parseGrammar(kFan, "fan.grammar");
    const auto geometric = geometricRules(g);
    const GenomeLimits limits{20};
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        Rng rng(seed);
        Chromosome c;
        ASSERT_TRUE(growNextObject(g, c, rng, limits, GrowthOrder::Chromosome, geometric));
        EXPECT_EQ(c.genes, 1u) << "the root alone is the first geometric object";
        std::uint32_t objects = 1;
        while (growNextObject(g, c, rng, limits, GrowthOrder::Chromosome, geometric)) {
            ++objects;
            EXPECT_EQ(geometricGenes(g, c, geometric), objects) << "exactly one new object per call";
            EXPECT_TRUE(decidedArePrefix(g, c));
            ASSERT_EQ(validateChromosome(g, c, limits), "");
        }
        EXPECT_EQ(undecidedChildren(g, c), 0u) << "growth stops only when every future is decided";
        EXPECT_EQ(c.child(0, 0), kRefused) << "a prob-0 slot is decided, as refused";
        for (std::uint32_t k = 0; k < 4; ++k) EXPECT_NE(c.child(0, 1 + k), kNotExpressed);
        EXPECT_EQ(validateChromosome(g, c, limits), "");
    }
}

TEST(SequentialGrowth, RefusedFuturesAreNeverGrownAgain) {
    const Grammar g = parseGrammar(kFan, "fan.grammar");
    const auto geometric = geometricRules(g);
    Rng rng(3);
    Chromosome c;
    while (growNextObject(g, c, rng, GenomeLimits{20}, GrowthOrder::Random, geometric)) {
    }
    const Chromosome done = c;
    for (int k = 0; k < 50; ++k) {
        EXPECT_FALSE(growNextObject(g, c, rng, GenomeLimits{20}, GrowthOrder::Random, geometric));
        EXPECT_FALSE(growNextObject(g, c, rng, GenomeLimits{20}, GrowthOrder::Chromosome, geometric));
    }
    EXPECT_EQ(c, done);
}

/// Eight optional positions that are almost always expressed: the first future decided is the
/// one that grows.
const char* kEight = R"(
start R
rule R { box child Y prob 0.999 max 8 }
rule Y { box }
)";

TEST(SequentialGrowth, SosmcPicksTheNextFutureUniformlyAtRandom) {
    const Grammar g = parseGrammar(kEight, "eight.grammar");
    const auto geometric = geometricRules(g);
    const GenomeLimits limits{20};
    std::array<int, 8> firstSmc{}, firstSosmc{};
    const int runs = 4000;
    for (int seed = 1; seed <= runs; ++seed) {
        for (GrowthOrder order : {GrowthOrder::Chromosome, GrowthOrder::Random}) {
            Rng rng{std::uint64_t(seed)};
            Chromosome c;
            growNextObject(g, c, rng, limits, order, geometric);  // the root
            ASSERT_TRUE(growNextObject(g, c, rng, limits, order, geometric));
            for (std::uint32_t k = 0; k < 8; ++k)
                if (c.child(0, k) > 0) ++(order == GrowthOrder::Chromosome ? firstSmc : firstSosmc)[k];
            ASSERT_EQ(validateChromosome(g, c, limits), "");
        }
    }
    EXPECT_GT(firstSmc[0], runs * 99 / 100) << "SMC takes the first future in chromosome order";
    // SOSMC: uniform over the 8 positions; chi-square with 7 degrees of freedom, p = 0.001 bound 24.3
    double chi2 = 0;
    for (int n : firstSosmc) chi2 += (n - runs / 8.0) * (n - runs / 8.0) / (runs / 8.0);
    EXPECT_LT(chi2, 24.3);
}

TEST(SequentialGrowth, FuturesThatWouldPassTheGeneLimitAreRefused) {
    const Grammar g = parseGrammar(kEight, "eight.grammar");
    const auto geometric = geometricRules(g);
    Rng rng(5);
    Chromosome c;
    while (growNextObject(g, c, rng, GenomeLimits{4}, GrowthOrder::Chromosome, geometric)) {
    }
    EXPECT_EQ(c.genes, 4u);
    EXPECT_EQ(undecidedChildren(g, c), 0u);
    EXPECT_EQ(validateChromosome(g, c, GenomeLimits{4}), "");
}

TEST(SequentialGrowth, ShippedGrammarsStayValidUnderBothOrders) {
    for (const char* file : {"grammars/spaceship.grammar", "grammars/coral.grammar"}) {
        const Grammar g = loadGrammar(test::sourcePath(file));
        const auto geometric = geometricRules(g);
        const GenomeLimits limits{60};
        for (std::uint64_t seed = 1; seed <= 100; ++seed) {
            Rng rng(seed);
            Chromosome c;
            const GrowthOrder order = seed % 2 ? GrowthOrder::Chromosome : GrowthOrder::Random;
            for (int step = 0; step < 80 && growNextObject(g, c, rng, limits, order, geometric); ++step)
                ASSERT_EQ(validateChromosome(g, c, limits), "") << file << " seed " << seed;
        }
    }
}

}  // namespace
}  // namespace shapevo
