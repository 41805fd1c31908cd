// Property tests: 10,000 random sequences of grow, cut, alter and crossover on the shipped grammars
// and on every shipped procedural content graph (grammars/pcg/*.pcg) always leave valid
// derivations (validate.hpp lists the invariants checked). A grammar without child slots (one
// gene, as window.pcg) gives grow, cut and crossover nothing to do: only alter acts on it.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "genome/validate.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace operator_properties_test {

/// Every shipped procedural content graph, relative to the source folder, sorted.
std::vector<std::string> shippedGraphFiles() {
    std::vector<std::string> relative;
    for (const std::string& path : test::shippedGrammarFiles())
        if (std::filesystem::path(path).extension() == ".pcg")
            relative.push_back(std::filesystem::relative(path, test::sourcePath("")).string());
    return relative;
}

/// `sequences` random sequences of 1 to 4 operators on a population of 8 chromosomes of the
/// grammar at `path` (relative to the source folder), each result validated; every operator that
/// can act on the grammar must have acted more than `sequences / 10` times.
void runOperatorSequences(const std::string& path, int sequences) {
    const Grammar g = loadGrammar(test::sourcePath(path));
    const GenomeLimits limits{60};
    Rng rng(12345);
    GenomeScratch scratch;
    // A small population that operators act on, so crossover mixes lineages.
    std::vector<Chromosome> pop(8), next(8);
    for (auto& c : pop) {
        const std::uint32_t target = 1 + rng.below(limits.maxGenes);
        while (c.genes < target && grow(g, c, rng, limits)) {
        }
        ASSERT_EQ(validateChromosome(g, c, limits), "");
    }
    int grows = 0, cuts = 0, alters = 0, crossovers = 0;
    for (int sequence = 0; sequence < sequences; ++sequence) {
        const int steps = 1 + int(rng.below(4));
        for (int s = 0; s < steps; ++s) {
            const std::uint32_t i = rng.below(8), j = rng.below(8);
            switch (rng.below(4)) {
            case 0: grows += grow(g, pop[i], rng, limits); break;
            case 1: cuts += cut(g, pop[i], rng, scratch); break;
            case 2: alters += alter(g, pop[i], rng); break;
            default: {
                crossovers += crossover(g, pop[i], pop[j], next[0], next[1], rng, limits, 3, scratch);
                pop[i] = next[0];
                pop[j] = next[1];
            }
            }
            const std::string e1 = validateChromosome(g, pop[i], limits);
            const std::string e2 = validateChromosome(g, pop[j], limits);
            ASSERT_EQ(e1, "") << "sequence " << sequence;
            ASSERT_EQ(e2, "") << "sequence " << sequence;
        }
    }
    // Every operator really ran many times (the test would prove nothing otherwise).
    EXPECT_GT(alters, sequences / 10);
    const bool hasChildSlots = std::any_of(g.rules.begin(), g.rules.end(), [](const Rule& r) { return !r.slots.empty(); });
    if (!hasChildSlots) {
        EXPECT_EQ(grows + cuts + crossovers, 0) << "one gene: nothing to grow, cut or swap";
        return;
    }
    EXPECT_GT(crossovers, sequences / 10);
    const bool optionalSlots = std::any_of(g.rules.begin(), g.rules.end(), [](const Rule& r) {
        return std::any_of(r.slots.begin(), r.slots.end(), [](const Slot& s) { return !s.mandatory(); });
    });
    if (!optionalSlots) {  // houses.grammar: every child is always there
        EXPECT_EQ(grows + cuts, 0) << "only mandatory children: nothing to grow or cut";
        return;
    }
    EXPECT_GT(grows, sequences / 10);
    EXPECT_GT(cuts, sequences / 10);
}

/// A test name from a grammar's path: "grammars/pcg/tree.pcg" -> "grammars_pcg_tree_pcg".
std::string pathTestName(const ::testing::TestParamInfo<std::string>& info) {
    std::string n = info.param;
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

class OperatorProperties : public ::testing::TestWithParam<std::string> {};

TEST_P(OperatorProperties, TenThousandRandomOperatorSequencesKeepEveryInvariant) { runOperatorSequences(GetParam(), 10000); }

INSTANTIATE_TEST_SUITE_P(ShippedGrammars, OperatorProperties,
                         ::testing::Values("grammars/spaceship.grammar", "grammars/coral.grammar", "grammars/tree.grammar",
                                           "grammars/city.grammar", "grammars/city-filling.grammar",
                                           "grammars/castle.grammar", "grammars/building.grammar", "grammars/houses.grammar",
                                           "grammars/city-zones.grammar", "grammars/street-numbers.grammar",
                                           "grammars/street-view.grammar", "grammars/carried-tree.grammar"));

INSTANTIATE_TEST_SUITE_P(ShippedGraphFiles, OperatorProperties, ::testing::ValuesIn(shippedGraphFiles()), pathTestName);

TEST(OperatorPropertiesFiles, TheShippedGraphFilesAreAllThere) {  // an empty list would run nothing and pass
    const std::vector<std::string> files = shippedGraphFiles();
    for (const char* shipped : {"grammars/pcg/tree.pcg", "grammars/pcg/window.pcg", "grammars/pcg/street.pcg"})
        EXPECT_NE(std::find(files.begin(), files.end(), shipped), files.end()) << shipped;
}

TEST(Cut, NeverRemovesMandatoryChildren) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/coral.grammar"));
    Rng rng(7);
    GenomeScratch scratch;
    Chromosome c;
    plantRoot(g, c, rng);
    ASSERT_EQ(c.genes, 3u);  // Root + its two mandatory Stems
    // Cutting can only remove optional children; with none expressed there is nothing to cut.
    EXPECT_FALSE(cut(g, c, rng, scratch));
    EXPECT_EQ(c.genes, 3u);
}

TEST(Cut, RemovesTheWholeSubtreeAndKeepsTheRestIntact) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    Rng rng(3);
    GenomeScratch scratch;
    const GenomeLimits limits{100};
    for (int trial = 0; trial < 200; ++trial) {
        Chromosome c;
        while (c.genes < 30 && grow(g, c, rng, limits)) {
        }
        const std::uint32_t before = c.genes;
        if (!cut(g, c, rng, scratch)) continue;
        EXPECT_LT(c.genes, before);
        EXPECT_EQ(validateChromosome(g, c, limits), "");
    }
}

TEST(Crossover, SwapsSubtreesOnTheSameGeneratorEdgeOnly) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    Rng rng(11);
    GenomeScratch scratch;
    const GenomeLimits limits{100};
    Chromosome a, b, ca, cb;
    while (a.genes < 25 && grow(g, a, rng, limits)) {
    }
    while (b.genes < 25 && grow(g, b, rng, limits)) {
    }
    ASSERT_TRUE(crossover(g, a, b, ca, cb, rng, limits, 3, scratch));
    // Genes are conserved: what one child lost, the other gained.
    EXPECT_EQ(ca.genes + cb.genes, a.genes + b.genes);
    EXPECT_EQ(validateChromosome(g, ca, limits), "");
    EXPECT_EQ(validateChromosome(g, cb, limits), "");
}

TEST(Grow, RespectsTheGeneLimit) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/coral.grammar"));
    Rng rng(5);
    const GenomeLimits limits{20};
    Chromosome c;
    int n = 0;
    while (grow(g, c, rng, limits) && n < 1000) ++n;
    EXPECT_LE(c.genes, 20u);
    EXPECT_EQ(validateChromosome(g, c, limits), "");
}

TEST(Validate, DetectsACorruptedOffset) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    Rng rng(9);
    const GenomeLimits limits{100};
    Chromosome c;
    while (c.genes < 10 && grow(g, c, rng, limits)) {
    }
    ASSERT_EQ(validateChromosome(g, c, limits), "");
    const std::uint32_t body = g.rules[c.rule(0)].geneWords();  // the first B follows S
    const Rule& bodyRule = g.rules[c.rule(body)];
    Chromosome badParent = c;
    badParent.setParentOffset(body, -1);  // points into the middle of S
    Chromosome badRule = c;
    badRule.words[0] = 999;
    Chromosome badParam = c;
    badParam.setParam(body, bodyRule, 0, 1e9f);  // far outside uniform(0.6, 1.5)
    Chromosome badCount = c;
    badCount.genes += 1;
    EXPECT_NE(validateChromosome(g, badParent, limits), "");
    EXPECT_NE(validateChromosome(g, badRule, limits), "");
    EXPECT_NE(validateChromosome(g, badParam, limits), "");
    EXPECT_NE(validateChromosome(g, badCount, limits), "");
}

}  // namespace operator_properties_test
}  // namespace shapevo
