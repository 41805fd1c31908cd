// Nudge (genome/nudge.hpp): one parameter moves, by a small step, and stays in its prior's
// support; nothing else of the chromosome changes; supports with a single value never move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../test_support.hpp"
#include "genome/nudge.hpp"
#include "genome/operators.hpp"
#include "genome/priors.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

/// Positions of the words of `c` that differ from `x` (same length assumed).
std::vector<std::size_t> changedWords(const Chromosome& x, const Chromosome& c) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < x.words.size(); ++i)
        if (x.words[i] != c.words[i]) out.push_back(i);
    return out;
}

TEST(Nudge, OnEveryShippedGrammarMovesExactlyOneParameterInsideItsSupport) {
    for (const char* file : {"grammars/spaceship.grammar", "grammars/coral.grammar", "grammars/tree.grammar",
                             "grammars/castle.grammar", "grammars/building.grammar", "grammars/city.grammar"}) {
        const Grammar g = loadGrammar(test::sourcePath(file));
        const GenomeLimits limits{60};
        Rng rng(5);
        int nudged = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            Chromosome x;
            const std::uint32_t length = 1 + rng.below(40);
            while (x.genes < length && grow(g, x, rng, limits)) {
            }
            Chromosome y = x;
            if (!nudge(g, y, rng)) {
                EXPECT_EQ(y.words, x.words) << file << ": a refused nudge changes nothing";
                continue;
            }
            ++nudged;
            ASSERT_EQ(validateChromosome(g, y, limits), "") << file << " trial " << trial;
            ASSERT_EQ(y.words.size(), x.words.size());
            ASSERT_EQ(changedWords(x, y).size(), 1u) << file << " trial " << trial;
            // The changed word is a parameter of some gene, and its value is in the prior's support.
            const std::size_t w = changedWords(x, y)[0];
            bool found = false;
            for (std::uint32_t pos = 0; pos < y.size(); pos += g.rules[y.rule(pos)].geneWords()) {
                const Rule& r = g.rules[y.rule(pos)];
                for (const Param& p : r.params)
                    for (int k = 0; k < p.dims; ++k) {
                        const std::uint32_t i = p.first + std::uint32_t(k);
                        if (pos + 2 + r.childOffsets + i != w) continue;
                        found = true;
                        EXPECT_TRUE(inSupport(g, p.prior[k], y.param(pos, r, i))) << file << " " << p.name;
                    }
            }
            EXPECT_TRUE(found) << file << ": word " << w << " is not a parameter";
        }
        EXPECT_GT(nudged, 2000) << file;
    }
}

const char* kPriorsGrammar = "start A\nrule A {\n"
                             "  param u = uniform(0, 10)\n"
                             "  param n = normal(5, 2) in [0, 10]\n"
                             "  param i = int(1, 4)\n"
                             "  param c = choice(1, 2, 3)\n"
                             "  box\n}\n";

TEST(Nudge, StepsAreSmallForContinuousPriorsAndOneForIntegers) {
    const Grammar g = parseGrammar(kPriorsGrammar, "priors.grammar");
    const Rule& r = g.rules[0];
    Rng rng(9);
    std::vector<double> steps[2];
    for (int trial = 0; trial < 20000; ++trial) {
        Chromosome x;
        plantRoot(g, x, rng);
        Chromosome y = x;
        ASSERT_TRUE(nudge(g, y, rng));
        for (std::uint32_t i = 0; i < 4; ++i) {
            const float a = x.param(0, r, i), b = y.param(0, r, i);
            if (a == b) continue;
            if (i < 2) steps[i].push_back(std::fabs(double(b) - double(a)));
            if (i == 2) EXPECT_EQ(std::fabs(b - a), 1.0f);
            if (i == 3) EXPECT_TRUE(b == 1 || b == 2 || b == 3);
        }
    }
    for (auto& s : steps) {
        ASSERT_GT(s.size(), 4000u);  // each of the four parameters is picked about a quarter of the time
        std::nth_element(s.begin(), s.begin() + std::ptrdiff_t(s.size() / 2), s.end());
        // A redraw from the prior (alter) moves a uniform(0, 10) value by 3.3 in the median; a
        // nudge's median step is a few hundredths of the width.
        EXPECT_LT(s[s.size() / 2], 0.6);
        EXPECT_GT(*std::max_element(s.begin(), s.end()), 0.5) << "coarse steps happen too";
    }
}

TEST(Nudge, SingleValuedSupportsNeverMove) {
    const Grammar g = parseGrammar("start A\nrule A {\n  param u = uniform(2, 2)\n  param c = choice(3, 3)\n"
                                   "  param i = int(4, 4)\n  box\n}\n",
                                   "fixed.grammar");
    Rng rng(1);
    Chromosome x;
    plantRoot(g, x, rng);
    Chromosome y = x;
    EXPECT_FALSE(nudge(g, y, rng));
    EXPECT_EQ(y.words, x.words);
}

}  // namespace
}  // namespace shapevo
