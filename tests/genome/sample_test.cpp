// Uncontrolled derivations (shapevo sample): each sibling position is expressed independently
// with its slot's prob, recursively, and the --min-genes / --max-genes window is met by
// rejection. The statistics run over fixed seeds, so they are deterministic; each tolerance is
// 5 binomial standard deviations, so a correct sampler passes with almost any seeds and the
// old sampler (the GA's grow until --min-genes, which with the default 1 expresses nothing)
// fails by far.
#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"
#include "genome/sample.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

// Root entries: A = 0, B = 1, C = 2..5, R = 6; R's own entry 0 continues the chain.
const char* kSlots = R"(
start S
rule S { box child A prob 0.05 child B prob 0.95 child C prob 0.3 max 4 child R prob 0.5 }
rule A { box }
rule B { box }
rule C { box }
rule R { box child R prob 0.5 }
)";

constexpr int kSamples = 2000;

/// Binomial standard deviation of a frequency over kSamples draws.
double sigma(double p) { return std::sqrt(p * (1 - p) / kSamples); }

TEST(UncontrolledSample, EachPositionFollowsItsProbability) {
    const Grammar g = parseGrammar(kSlots, "slots.grammar");
    const GenomeLimits limits{100};
    int a = 0, b = 0, noC = 0, c01 = 0, rootR = 0, secondR = 0;
    int c[4] = {0, 0, 0, 0};
    for (int seed = 1; seed <= kSamples; ++seed) {
        Rng rng{std::uint64_t(seed)};  // as `shapevo sample --seed N` seeds it
        Chromosome x;
        const SampleOutcome o = sampleDerivation(g, x, rng, 1, limits.maxGenes, 1000);
        ASSERT_TRUE(o.found) << seed;
        ASSERT_EQ(o.attempts, 1u) << "the window [1, 100] never interferes with this grammar";
        ASSERT_EQ(validateChromosome(g, x, limits), "") << seed;
        a += x.child(0, 0) > 0;
        b += x.child(0, 1) > 0;
        int cs = 0;
        for (int k = 0; k < 4; ++k) {
            const bool on = x.child(0, 2 + std::uint32_t(k)) > 0;
            c[k] += on;
            cs += on;
        }
        noC += cs == 0;
        c01 += x.child(0, 2) > 0 && x.child(0, 3) > 0;
        if (const std::int32_t r = x.child(0, 6); r > 0) {
            ++rootR;
            secondR += x.child(std::uint32_t(r), 0) > 0;
        }
    }
    const double n = kSamples;
    EXPECT_NEAR(a / n, 0.05, 5 * sigma(0.05)) << "A: prob 0.05";
    EXPECT_NEAR(b / n, 0.95, 5 * sigma(0.95)) << "B: prob 0.95";
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c[k] / n, 0.3, 5 * sigma(0.3)) << "C position " << k << " of max 4";
    EXPECT_NEAR(noC / n, std::pow(0.7, 4), 5 * sigma(std::pow(0.7, 4))) << "the four C positions are independent";
    EXPECT_NEAR(c01 / n, 0.09, 5 * sigma(0.09)) << "C positions 0 and 1 together";
    EXPECT_NEAR(rootR / n, 0.5, 5 * sigma(0.5)) << "R below the root";
    ASSERT_GT(rootR, 0);
    EXPECT_NEAR(double(secondR) / rootR, 0.5, 5 * std::sqrt(0.25 / rootR)) << "R below R: decided again, recursively";
}

TEST(UncontrolledSample, TheGeneWindowIsMetByRetrying) {
    const Grammar g = parseGrammar(kSlots, "slots.grammar");
    int retried = 0;
    for (int seed = 1; seed <= 200; ++seed) {
        Rng rng{std::uint64_t(seed)};
        Chromosome x;
        const SampleOutcome o = sampleDerivation(g, x, rng, 5, 6, 10000);
        ASSERT_TRUE(o.found) << seed;
        EXPECT_GE(x.genes, 5u);
        EXPECT_LE(x.genes, 6u);
        EXPECT_EQ(validateChromosome(g, x, GenomeLimits{6}), "");
        retried += o.attempts > 1;
    }
    EXPECT_GT(retried, 0);
}

TEST(UncontrolledSample, AnImpossibleWindowGivesUpAfterTheAttempts) {
    const Grammar g = parseGrammar("start S\nrule S { box child A prob 0.5 max 2 }\nrule A { box }\n", "small.grammar");
    Rng rng(3);
    Chromosome x;
    const SampleOutcome o = sampleDerivation(g, x, rng, 4, 10, 50);  // at most 3 genes exist
    EXPECT_FALSE(o.found);
    EXPECT_EQ(o.attempts, 50u);
    EXPECT_TRUE(x.empty());
}

TEST(UncontrolledSample, ABoundBelowTheMandatoryGenesStopsGrowing) {
    const Grammar g = parseGrammar("start S\nrule S { box child A max 3 }\nrule A { box }\n", "fixed.grammar");
    Rng rng(1);
    Chromosome x;
    EXPECT_FALSE(growUncontrolled(g, x, rng, 3));
    EXPECT_LE(x.genes, 3u);
    EXPECT_TRUE(growUncontrolled(g, x, rng, 4));
    EXPECT_EQ(x.genes, 4u);
}

TEST(UncontrolledSample, SameSeedSameDerivation) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/coral.grammar"));
    Chromosome x, y;
    Rng r1(42), r2(42);
    ASSERT_TRUE(sampleDerivation(g, x, r1, 1, 100, 1000).found);
    ASSERT_TRUE(sampleDerivation(g, y, r2, 1, 100, 1000).found);
    EXPECT_EQ(x, y);
}

}  // namespace
}  // namespace shapevo
