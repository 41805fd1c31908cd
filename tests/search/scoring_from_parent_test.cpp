// Scoring from the parent (score/image/image_from_parent.cpp): children that grow, cut, alter and
// crossover made of evaluated models carry their lineage to the Evaluator, which scores them
// from the parent's coverage counts — with the fitness the full evaluation gives, bit for bit, on
// every shipped image scene (trees, cities of boxes, streets of split buildings); most children
// of those operators are scored that way; a lineage that does not fit the chromosomes is not used.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "run/scene.hpp"
#include "score/image/image_scorer.hpp"
#include "search/evaluation_batch.hpp"
#include "search/evaluator.hpp"

namespace shapevo {
namespace {

struct ScenePair {
    RunSettings settings;
    std::unique_ptr<Grammar> grammar;
    std::unique_ptr<Scene> incremental, full;
};

ScenePair loadScenes(const std::string& name, double cacheMb = 16) {
    ScenePair p;
    p.settings = loadConfig(test::sourcePath("configs/" + name + ".toml"));
    p.grammar = std::make_unique<Grammar>(loadGrammar(p.settings.grammarPath, p.settings.grammarAttrs));
    RunSettings on = p.settings, off = p.settings;
    on.incremental.enabled = true;
    on.incremental.cacheMb = cacheMb;
    off.incremental.enabled = false;
    p.incremental = Scene::load(on, *p.grammar);
    p.full = Scene::load(off, *p.grammar);
    return p;
}

class ScoringFromParent : public ::testing::TestWithParam<std::string> {};

/// Evolve `s`'s scene 60 generations of 12 children (grow, cut, alter, crossover) on one thread,
/// each child checked against the full evaluation (then `afterScoring()`); returns how many
/// children there were.
std::size_t evolveChecked(ScenePair& s, Evaluator& evaluator, const std::string& name,
                          const std::function<void()>& afterScoring = [] {}) {
    const Grammar& g = *s.grammar;
    const GenomeLimits limits = s.settings.limits;
    auto fullWorkspace = s.full->scorer().makeWorkspace();
    Rng rng(7);
    GenomeScratch scratch;
    Population pop;
    pop.individuals.resize(12);
    for (Chromosome& c : pop.individuals) growRandomLength(g, c, rng, limits, 20, 80);
    evaluator.evaluate(pop);
    std::size_t children = 0;
    Population next;
    for (int generation = 0; generation < 60; ++generation) {
        next.individuals.assign(pop.individuals.size(), Chromosome{});
        for (std::size_t i = 0; i < pop.size(); i += 2) {
            const Chromosome& a = pop.individuals[rng.below(std::uint32_t(pop.size()))];
            const Chromosome& b = pop.individuals[rng.below(std::uint32_t(pop.size()))];
            Chromosome &x = next.individuals[i], &y = next.individuals[i + 1];
            switch (rng.below(4)) {
            case 0: x = a; y = b; grow(g, x, rng, limits); grow(g, y, rng, limits); break;
            case 1: x = a; y = b; cut(g, x, rng, scratch); cut(g, y, rng, scratch); break;
            case 2: x = a; y = b; alter(g, x, rng); alter(g, y, rng); break;
            default: crossover(g, a, b, x, y, rng, limits, 3, scratch); break;
            }
        }
        evaluator.evaluate(next);
        afterScoring();
        for (std::size_t i = 0; i < next.size(); ++i) {
            const double full = s.full->scorer().fitness(next.individuals[i], *fullWorkspace);
            if (next.fitness[i] != full) {
                ADD_FAILURE() << name << ", generation " << generation << ", child " << i << ": " << next.fitness[i] << " against " << full;
                return children;
            }
            ++children;
        }
        // The better half of both goes on (children compete with their parents).
        for (std::size_t i = 0; i < pop.size(); ++i)
            if (next.fitness[i] > pop.fitness[i]) {
                std::swap(pop.individuals[i], next.individuals[i]);
                pop.fitness[i] = next.fitness[i];
            }
    }
    return children;
}

TEST_P(ScoringFromParent, ChildrenOfEveryOperatorScoreAsTheFullEvaluationDoes) {
    ScenePair s = loadScenes(GetParam());
    Evaluator evaluator(s.incremental->scorer(), 1);
    const std::size_t children = evolveChecked(s, evaluator, GetParam());
    // Most children were scored from their parents (the others: a change at the root, a duplicate).
    EXPECT_GT(evaluator.scoredFromParent(), children / 2) << "of " << children;
    EXPECT_FALSE(s.incremental->scorer().modelsFull());
}

INSTANTIATE_TEST_SUITE_P(ImageScenes, ScoringFromParent,
                         ::testing::Values("tree-logo", "tree-sketch", "city-whale", "street-whale", "city-shoe"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

TEST(ScoringFromParentLineage, UnderATightBoundModelsAreNotKeptAndScoresStayExact) {
    // With room for every model (score.cache_mb = 16), then with score.cache_mb = 1: the tree
    // sketch's models (their chromosomes and about 50 KB of coverage blocks each, 61 blocks of
    // 128 words for the 800 x 600 sketch) reach that within the first generations.
    ScenePair roomy = loadScenes("tree-sketch", 16);
    Evaluator roomyEvaluator(roomy.incremental->scorer(), 1);
    evolveChecked(roomy, roomyEvaluator, "tree-sketch");
    ScenePair s = loadScenes("tree-sketch", 1);
    Evaluator evaluator(s.incremental->scorer(), 1);
    const auto& scorer = static_cast<const ImageScorer&>(s.incremental->scorer());
    std::size_t most = 0;  // bytes the models held, after each generation's scoring
    evolveChecked(s, evaluator, "tree-sketch", [&] { most = std::max(most, scorer.models().bytesInUse()); });
    EXPECT_TRUE(scorer.modelsFull());
    EXPECT_FALSE(roomy.incremental->scorer().modelsFull());
    EXPECT_GT(most, scorer.models().bound() / 2);
    EXPECT_LE(most, scorer.models().bound());
    EXPECT_GT(evaluator.scoredFromParent(), 0u);  // some still were, from the models kept
    EXPECT_LT(evaluator.scoredFromParent(), roomyEvaluator.scoredFromParent());
}

TEST(ScoringFromParentLineage, ALineageThatDoesNotFitTheChromosomesIsNotUsed) {
    ScenePair s = loadScenes("tree-sketch");
    const Grammar& g = *s.grammar;
    Evaluator evaluator(s.incremental->scorer(), 1);
    auto fullWorkspace = s.full->scorer().makeWorkspace();
    Rng rng(3);
    Population pop;
    pop.individuals.resize(1);
    growRandomLength(g, pop.individuals[0], rng, s.settings.limits, 60, 80);
    evaluator.evaluate(pop);
    ASSERT_TRUE(pop.individuals[0].lineage.parent);
    Population child;
    child.individuals.push_back(pop.individuals[0]);
    ASSERT_TRUE(grow(g, child.individuals[0], rng, s.settings.limits));
    ASSERT_TRUE(child.individuals[0].lineage.changed());
    child.individuals[0].lineage.childGene = 0;  // claims the whole model is new, from the root
    child.individuals[0].lineage.parentGene = Lineage::kNone;
    evaluator.evaluate(child);
    EXPECT_EQ(evaluator.scoredFromParent(), 0u);
    EXPECT_EQ(child.fitness[0], s.full->scorer().fitness(child.individuals[0], *fullWorkspace));
}

}  // namespace
}  // namespace shapevo
