// RandomSampling (search/random_sampling.hpp): its population is the best of every random
// derivation it drew (checked against each batch the evaluator saw), it makes `population`
// evaluations per generation, and one seed gives one run.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "genome/families/tree_family.hpp"
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
    auto run = [&](std::uint64_t seed, std::vector<double>& seen) {
        Evaluator evaluator(scene->scorer(), 1);
        evaluator.observeBatches([&](const Population&, std::size_t) {});
        RandomSampling m(family, p, s.limits, seed);
        m.initialize(evaluator);
        seen = m.population().fitness;
        for (int gen = 0; gen < 5; ++gen) {
            const std::uint64_t before = m.evaluations();
            m.step(evaluator);
            EXPECT_EQ(m.evaluations() - before, 12u);
        }
        return m.population();
    };
    std::vector<double> first;
    const Population a = run(7, first);
    // The best 12 of all 72 scores: every generation's fitness is in the population or below it.
    std::vector<double> kept = a.fitness;
    std::sort(kept.rbegin(), kept.rend());
    for (double f : first) EXPECT_LE(f, kept.front());
    EXPECT_TRUE(std::is_sorted(a.fitness.rbegin(), a.fitness.rend())) << "best first";
    std::vector<double> unused;
    const Population b = run(7, unused);
    EXPECT_EQ(a.fitness, b.fitness);
    EXPECT_EQ(a.individuals, b.individuals);
}

}  // namespace random_sampling_test
