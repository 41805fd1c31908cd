// Jump move (cut + regrow): results are valid derivations, the cut subtree's values are reused
// where a new gene of the same rule takes the same place in canonical order, fresh values only
// where there is none, non-terminal selection never picks a terminal, and proposals past the
// gene limit are refused.
#include <gtest/gtest.h>

#include <set>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "genome/regrow.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

TEST(Regrow, JumpsOnShippedGrammarsKeepEveryInvariant) {
    for (const char* file : {"grammars/spaceship.grammar", "grammars/coral.grammar"}) {
        const Grammar g = loadGrammar(test::sourcePath(file));
        const GenomeLimits limits{60};
        Rng rng(11);
        RegrowScratch s;
        std::vector<MatchedGene> matched;
        int accepted = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            Chromosome x, y;
            const std::uint32_t length = 1 + rng.below(40);
            while (x.genes < length && grow(g, x, rng, limits)) {
            }
            for (double bias : {1.0, 0.5}) {
                const double total = jumpWeightTotal(g, x, bias, s);
                ASSERT_GT(total, 0);
                const std::uint32_t v = pickJumpGene(g, x, total, rng, s);
                ASSERT_FALSE(g.rules[x.rule(v)].slots.empty()) << "only non-terminals are picked";
                if (!regrowBelow(g, x, v, y, rng, limits, s, &matched)) continue;
                ++accepted;
                ASSERT_EQ(validateChromosome(g, y, limits), "") << file << " trial " << trial;
                for (const MatchedGene& m : matched) {
                    ASSERT_EQ(x.rule(m.from), y.rule(m.to));
                    const Rule& r = g.rules[x.rule(m.from)];
                    for (std::uint32_t i = 0; i < r.paramFloats; ++i)
                        ASSERT_EQ(x.param(m.from, r, i), y.param(m.to, r, i)) << "paired genes share values";
                }
            }
        }
        EXPECT_GT(accepted, 3000) << file;
    }
}

/// Every slot mandatory: regrowing gives back the same tree, and every value is reused.
const char* kFixed = R"(
start A
rule A { param a = uniform(0, 1) box child B max 2 }
rule B { param b = uniform(0, 1) box child C }
rule C { param c = uniform(0, 1) box }
)";

TEST(Regrow, SameShapeReusesEveryValue) {
    const Grammar g = parseGrammar(kFixed, "fixed.grammar");
    Rng rng(2);
    Chromosome x, y;
    plantRoot(g, x, rng);
    ASSERT_EQ(x.genes, 5u);
    RegrowScratch s;
    for (std::uint32_t v : {0u, std::uint32_t(x.child(0, 1))}) {
        ASSERT_TRUE(regrowBelow(g, x, v, y, rng, GenomeLimits{10}, s));
        EXPECT_EQ(y, x) << "regrown below " << v;
    }
}

/// B is optional with two alternatives; its values carry over only to a B, never to a D.
const char* kSwitch = R"(
start A
rule A { param a = uniform(0, 1) box child [1] B | [1] D prob 0.9 max 2 }
rule B { param b = uniform(0, 1) box }
rule D { param d = uniform(0, 1) box }
)";

TEST(Regrow, NewGenesTakeTheCutGenesValuesRuleByRuleInOrder) {
    const Grammar g = parseGrammar(kSwitch, "switch.grammar");
    const Rule& A = g.rules[0];
    Rng rng(9);
    RegrowScratch s;
    std::vector<MatchedGene> matched;
    int checked = 0;
    for (int trial = 0; trial < 500; ++trial) {
        Chromosome x, y;
        plantRoot(g, x, rng);
        while (grow(g, x, rng, GenomeLimits{3})) {
        }
        ASSERT_TRUE(regrowBelow(g, x, 0, y, rng, GenomeLimits{3}, s, &matched));
        EXPECT_EQ(y.param(0, A, 0), x.param(0, A, 0)) << "the jump gene keeps its own values";
        // old and new children in child-offset order, per rule
        std::vector<float> oldB, oldD, newB, newD;
        for (std::uint32_t e = 0; e < 2; ++e) {
            if (x.child(0, e) > 0) {
                const std::uint32_t p = std::uint32_t(x.child(0, e));
                (g.rules[x.rule(p)].name == "B" ? oldB : oldD).push_back(x.param(p, g.rules[x.rule(p)], 0));
            }
            if (y.child(0, e) > 0) {
                const std::uint32_t p = std::uint32_t(y.child(0, e));
                (g.rules[y.rule(p)].name == "B" ? newB : newD).push_back(y.param(p, g.rules[y.rule(p)], 0));
            }
        }
        for (std::size_t k = 0; k < std::min(oldB.size(), newB.size()); ++k, ++checked) EXPECT_EQ(newB[k], oldB[k]);
        for (std::size_t k = 0; k < std::min(oldD.size(), newD.size()); ++k, ++checked) EXPECT_EQ(newD[k], oldD[k]);
        std::set<float> old(oldB.begin(), oldB.end());
        old.insert(oldD.begin(), oldD.end());
        const std::size_t fresh = newB.size() - std::min(oldB.size(), newB.size()) + newD.size() - std::min(oldD.size(), newD.size());
        std::size_t reusedValues = 0;
        for (float v : newB) reusedValues += old.count(v);
        for (float v : newD) reusedValues += old.count(v);
        EXPECT_EQ(reusedValues + fresh, newB.size() + newD.size()) << "unpaired genes get fresh values";
        EXPECT_EQ(matched.size(), 1 + (newB.size() + newD.size() - fresh));
    }
    EXPECT_GT(checked, 300);
}

TEST(Regrow, JumpPastTheGeneLimitIsRefused) {
    const Grammar g = parseGrammar(kFixed, "fixed.grammar");
    Rng rng(1);
    Chromosome x, y;
    plantRoot(g, x, rng);
    RegrowScratch s;
    EXPECT_FALSE(regrowBelow(g, x, 0, y, rng, GenomeLimits{4}, s)) << "5 mandatory genes cannot fit in 4";
}

}  // namespace
}  // namespace shapevo
