// RandomSampling (search/random_sampling.hpp): its population is the best of every random
// derivation it drew (every chromosome the evaluator saw, scored again on its own), it makes
// `population` evaluations per generation, and one seed gives one run.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "run/scene.hpp"
#include "search/evaluator.hpp"
#include "search/random_sampling.hpp"
#include "../test_support.hpp"

namespace random_sampling_test {

using namespace shapevo;

TEST(RandomSampling, KeepsTheBestOfEveryDerivationDrawnWithPopulationEvaluationsAGeneration) {
    const RunSettings s = loadConfig(test::sourcePath("configs/spaceship.toml"));
    const Grammar g = loadGrammar(s.grammarPath, s.grammarAttrs);
    const std::unique_ptr<Scene> scene = Scene::load(s, g);
    const TreeFamily family(g);
    PopulationSettings p = s.population;
    p.population = 12;
    // Every chromosome handed to the evaluator, as it was handed over (before scoring).
    auto run = [&](std::uint64_t seed, std::vector<Chromosome>& drawn) {
        Evaluator evaluator(scene->scorer(), 1);
        evaluator.observeBatches([&](const Population& batch, std::size_t from) {
            drawn.insert(drawn.end(), batch.individuals.begin() + std::ptrdiff_t(from), batch.individuals.end());
        });
        RandomSampling m(family, p, s.limits, seed);
        m.initialize(evaluator);
        EXPECT_EQ(drawn.size(), 12u);
        for (int gen = 0; gen < 5; ++gen) {
            const std::uint64_t before = m.evaluations();
            m.step(evaluator);
            EXPECT_EQ(m.evaluations() - before, 12u);
        }
        return m.population();
    };
    std::vector<Chromosome> drawn;
    const Population a = run(7, drawn);
    ASSERT_EQ(drawn.size(), 72u) << "12 fresh derivations a generation: the first and 5 more";
    // Brute force: score all 72 on their own; the population is their best 12, best first.
    const std::unique_ptr<ScoreWorkspace> ws = scene->scorer().makeWorkspace();
    std::vector<double> all;
    for (const Chromosome& c : drawn) all.push_back(scene->scorer().fitness(c, *ws));
    std::sort(all.rbegin(), all.rend());
    all.resize(12);
    EXPECT_EQ(a.fitness, all);
    EXPECT_GT(std::set<double>(all.begin(), all.end()).size(), 1u) << "the drawn derivations differ";
    std::vector<Chromosome> again;
    const Population b = run(7, again);
    EXPECT_EQ(a.fitness, b.fitness);
    EXPECT_EQ(a.individuals, b.individuals);
}

}  // namespace random_sampling_test
