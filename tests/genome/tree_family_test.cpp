// TreeFamily: the derivation-tree family behind the model-family seam is the free operators of
// genome/operators.hpp, nudge.hpp and regrow.hpp, draw for draw. Random operator sequences applied
// through TreeOperators and through the free functions, from the same seed, give identical
// chromosomes, return values and Rng states (what keeps seeded runs byte-identical); check() is
// validateChromosome.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "genome/families/tree_family.hpp"
#include "genome/nudge.hpp"
#include "genome/operators.hpp"
#include "genome/regrow.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace tree_family_test {

/// The free functions, called as the search methods called them before the seam.
struct FreeOperators {
    const Grammar& g;
    GenomeLimits limits;
    GenomeScratch scratch;
    RegrowScratch regrow;

    bool apply(int op, std::vector<Chromosome>& pop, std::size_t i, std::size_t j, Chromosome& a, Chromosome& b, Rng& rng) {
        switch (op) {
        case 0: growRandomLength(g, pop[i], rng, limits, 1, 40); return true;
        case 1: return grow(g, pop[i], rng, limits);
        case 2: return cut(g, pop[i], rng, scratch);
        case 3: return alter(g, pop[i], rng);
        case 4: return nudge(g, pop[i], rng);
        case 5: {
            const bool crossed = crossover(g, pop[i], pop[j], a, b, rng, limits, 3, scratch);
            pop[i] = a;
            pop[j] = b;
            return crossed;
        }
        default: {
            const double total = jumpWeightTotal(g, pop[i], 1.0, regrow);
            if (!(total > 0)) return false;
            if (!regrowBelow(g, pop[i], pickJumpGene(g, pop[i], total, rng, regrow), a, rng, limits, regrow)) return false;
            pop[i] = a;
            return true;
        }
        }
    }
};

/// The same operation through the family's operators.
bool applyThroughFamily(GenomeOperators& ops, int op, std::vector<Chromosome>& pop, std::size_t i, std::size_t j,
                        Chromosome& a, Chromosome& b, Rng& rng) {
    switch (op) {
    case 0: ops.randomGenome(pop[i], rng, 1, 40); return true;
    case 1: return ops.grow(pop[i], rng);
    case 2: return ops.cut(pop[i], rng);
    case 3: return ops.alter(pop[i], rng);
    case 4: return ops.nudge(pop[i], rng);
    case 5: {
        const bool crossed = ops.crossover(pop[i], pop[j], a, b, rng, 3);
        pop[i] = a;
        pop[j] = b;
        return crossed;
    }
    default: {
        if (!ops.regrow(pop[i], a, rng)) return false;
        pop[i] = a;
        return true;
    }
    }
}

class TreeFamilyOperators : public ::testing::TestWithParam<const char*> {};

TEST_P(TreeFamilyOperators, GiveTheFreeFunctionsChromosomesDrawForDraw) {
    const Grammar g = loadGrammar(test::sourcePath(GetParam()));
    const GenomeLimits limits{50};
    const TreeFamily family(g);
    const std::unique_ptr<GenomeOperators> ops = family.makeOperators(limits);
    FreeOperators free{g, limits, {}, {}};
    Rng control(99);  // picks the operators and individuals; the operators draw from their own Rng
    int applied[7] = {}, refusedRegrows = 0;
    for (int sequence = 0; sequence < 400; ++sequence) {
        const std::uint64_t seed = 1000 + std::uint64_t(sequence);
        Rng viaFamily(seed), viaFree(seed);
        std::vector<Chromosome> p(4), q(4);
        Chromosome a1, b1, a2, b2;
        for (std::size_t k = 0; k < p.size(); ++k) {
            ops->randomGenome(p[k], viaFamily, 1, 30);
            growRandomLength(g, q[k], viaFree, limits, 1, 30);
        }
        const int steps = 1 + int(control.below(12));
        for (int s = 0; s < steps; ++s) {
            const int op = int(control.below(7));
            const std::size_t i = control.below(4), j = control.below(4);
            const bool r1 = applyThroughFamily(*ops, op, p, i, j, a1, b1, viaFamily);
            const bool r2 = free.apply(op, q, i, j, a2, b2, viaFree);
            ASSERT_EQ(r1, r2) << GetParam() << " sequence " << sequence << " step " << s << " op " << op;
            ASSERT_EQ(viaFamily.state(), viaFree.state()) << "sequence " << sequence << " step " << s << " op " << op;
            for (std::size_t k = 0; k < p.size(); ++k) {
                ASSERT_EQ(p[k], q[k]) << "sequence " << sequence << " step " << s << " op " << op << " individual " << k;
                ASSERT_EQ(family.check(p[k], limits), validateChromosome(g, p[k], limits));
                ASSERT_EQ(family.check(p[k], limits), "");
            }
            applied[op] += r1;
            refusedRegrows += op == 6 && !r1;
        }
    }
    for (int op = 0; op < 7; ++op) EXPECT_GT(applied[op], 50) << "operator " << op << " really ran";
    (void)refusedRegrows;
}

INSTANTIATE_TEST_SUITE_P(ShippedGrammars, TreeFamilyOperators,
                         ::testing::Values("grammars/spaceship.grammar", "grammars/coral.grammar"));

TEST(TreeFamily, NamesItsGrammarAndChecksLikeValidateChromosome) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    const TreeFamily family(g);
    EXPECT_EQ(family.name(), "derivation tree");
    EXPECT_EQ(family.treeGrammar(), &g);
    EXPECT_EQ(&family.sourceText(), &g.source);
    const GenomeLimits limits{60};
    Rng rng(3);
    Chromosome c;
    growRandomLength(g, c, rng, limits, 10, 20);
    EXPECT_EQ(family.check(c, limits), "");
    Chromosome badRule = c;
    badRule.words[0] = 9999;
    EXPECT_EQ(family.check(badRule, limits), validateChromosome(g, badRule, limits));
    EXPECT_NE(family.check(badRule, limits), "");
    EXPECT_EQ(family.check(c, GenomeLimits{2}), validateChromosome(g, c, GenomeLimits{2}));
    EXPECT_NE(family.check(c, GenomeLimits{2}), "");
}

TEST(TreeFamily, RegrowOfAGenomeWithoutNonTerminalsDrawsNothing) {
    // A grammar whose start rule has no child slots: nothing to regrow below.
    const Grammar g = parseGrammar("start Box\nrule Box {\n  box\n}\n", "box.grammar");
    const TreeFamily family(g);
    const auto ops = family.makeOperators(GenomeLimits{10});
    Rng rng(5);
    Chromosome x, y;
    ops->randomGenome(x, rng, 1, 1);
    ASSERT_EQ(x.genes, 1u);
    const auto before = rng.state();
    EXPECT_FALSE(ops->regrow(x, y, rng));
    EXPECT_EQ(rng.state(), before) << "a regrow with no point to regrow below must not draw (the hybrid relies on it)";
}

}  // namespace tree_family_test
}  // namespace shapevo
