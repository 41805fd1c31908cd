// Search methods and model families: the table says which methods need a derivation tree.
// makeSearchMethod refuses SMC, SOSMC and RJMCMC for a family without a tree grammar (an
// InputError naming the config file, search.method, the method and those that can run it) and
// builds the GA and the hybrid for any family, which then breed it through its operators only.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/input_error.hpp"
#include "genome/families/tree_family.hpp"
#include "genome/genome_family.hpp"
#include "grammar/front_ends.hpp"
#include "search/search_methods.hpp"
#include "function_scorer.hpp"
#include "../small_tree_grammar.hpp"

namespace shapevo {
namespace search_method_family_test {

/// A genome of one word, a counter: grow adds one, cut takes one, alter and nudge redraw it.
class CounterOperators final : public GenomeOperators {
public:
    void randomGenome(Chromosome& c, Rng& rng, std::uint32_t, std::uint32_t) override {
        c.clear();
        c.words = {rng.below(100)};
        c.genes = 1;
    }
    bool grow(Chromosome& c, Rng&) override { return ++c.words[0], true; }
    bool cut(Chromosome& c, Rng&) override { return c.words[0] > 0 && (--c.words[0], true); }
    bool alter(Chromosome& c, Rng& rng) override { return c.words[0] = rng.below(100), true; }
    bool nudge(Chromosome& c, Rng& rng) override { return c.words[0] += rng.below(3), true; }
    bool crossover(const Chromosome& a, const Chromosome& b, Chromosome& childA, Chromosome& childB, Rng&,
                   int) override {
        childA = b;
        childB = a;
        return true;
    }
    bool regrow(const Chromosome&, Chromosome&, Rng&) override { return false; }
};

/// A family without a tree grammar.
class CounterFamily final : public GenomeFamily {
public:
    std::string_view name() const override { return "counter"; }
    std::unique_ptr<GenomeOperators> makeOperators(const GenomeLimits&) const override {
        return std::make_unique<CounterOperators>();
    }
    std::string check(const Chromosome& c, const GenomeLimits&) const override {
        return c.genes == 1 && c.words.size() == 1 ? "" : "not one counter";
    }
    const std::string& sourceText() const override { return text_; }
    const Grammar* treeGrammar() const override { return nullptr; }

private:
    std::string text_ = "counter";
};

TEST(SearchMethodFamilies, MethodsThatNeedATreeAreRefusedForAFamilyWithoutOne) {
    const CounterFamily family;
    PopulationSettings sizes;
    sizes.population = 10;
    GaSettings ga;
    ga.elitism = 2;
    ga.tournament = 2;
    int refused = 0;
    for (const SearchMethodEntry& m : searchMethods()) {
        SearchSettings s;
        s.method = std::string(m.name);
        SCOPED_TRACE(s.method);
        const bool tree = s.method == "smc" || s.method == "sosmc" || s.method == "rjmcmc";
        ASSERT_EQ(m.needsTree, tree) << "the table says which methods need a tree";
        if (!m.needsTree) {
            EXPECT_EQ(methodFamilyProblem(s, family), "");
            EXPECT_NE(makeSearchMethod(s, sizes, ga, family, GenomeLimits{10}, 1, "run.toml"), nullptr);
            continue;
        }
        ++refused;
        try {
            makeSearchMethod(s, sizes, ga, family, GenomeLimits{10}, 1, "configs/x.toml");
            ADD_FAILURE() << "accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), "configs/x.toml");
            EXPECT_EQ(e.where(), "search.method");
            EXPECT_EQ(e.message(), "search.method = \"" + s.method +
                                       "\" needs a derivation-tree grammar (a \".grammar\", \".rule\" or \".pcg\" file); counter "
                                       "genomes run with \"hybrid\", \"ga\" or \"random\"");
        }
    }
    EXPECT_EQ(refused, 3) << "smc, sosmc and rjmcmc need a tree";
}

TEST(SearchMethodFamilies, EveryMethodAcceptsTheTreeFamily) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const TreeFamily family(g);
    for (const SearchMethodEntry& m : searchMethods()) {
        SearchSettings s;
        s.method = std::string(m.name);
        EXPECT_EQ(methodFamilyProblem(s, family), "") << s.method;
    }
}

TEST(SearchMethodFamilies, GaAndHybridBreedAFamilyThroughItsOperatorsOnly) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");  // the scorer's; the genomes are counters
    const CounterFamily family;
    test::FunctionScorer scorer(g, [](const Chromosome& c) { return -std::abs(double(c.words[0]) - 500.0); });
    Evaluator evaluator(scorer, 1);
    PopulationSettings sizes;
    sizes.population = 20;
    GaSettings ga;
    ga.elitism = 2;
    ga.tournament = 3;
    for (const char* name : {"ga", "hybrid"}) {
        SearchSettings s;
        s.method = name;
        auto method = makeSearchMethod(s, sizes, ga, family, GenomeLimits{10}, 7, "run.toml");
        method->initialize(evaluator);
        const double first = method->stats().best;
        while (method->generation() < 30) method->step(evaluator);
        EXPECT_GT(method->stats().best, first) << name;
        for (const Chromosome& c : method->population().individuals) EXPECT_EQ(family.check(c, GenomeLimits{10}), "") << name;
    }
}

}  // namespace search_method_family_test
}  // namespace shapevo
