// Selection: k-tournament returns the best of its draws; the roulette wheel picks in proportion
// to fitness shifted by the worst; the GA keeps its elite.
#include <gtest/gtest.h>

#include "search/selection.hpp"

namespace shapevo {
namespace {

TEST(Tournament, WithTheWholePopulationAlmostAlwaysFindsTheBest) {
    const std::vector<double> f = {0.1, 0.9, 0.3, 0.5};
    Rng rng(1);
    int best = 0;
    for (int i = 0; i < 1000; ++i) best += tournamentSelect(f, 20, rng) == 1;
    EXPECT_GT(best, 990);  // missing index 1 in 20 draws has probability 0.75^20 = 0.3 %
}

TEST(Tournament, SizeOneIsUniform) {
    const std::vector<double> f = {5, 1, 3, 2};
    Rng rng(2);
    std::vector<int> n(4, 0);
    for (int i = 0; i < 40000; ++i) ++n[tournamentSelect(f, 1, rng)];
    for (int c : n) EXPECT_NEAR(c, 10000, 400);
}

TEST(Roulette, PicksInProportionToFitnessAboveTheWorst) {
    const std::vector<double> f = {-1.0, 0.0, 1.0, 3.0};  // shifted: 0, 1, 2, 4 (+ a tiny floor)
    RouletteWheel w;
    w.prepare(f);
    Rng rng(3);
    std::vector<int> n(4, 0);
    const int draws = 70000;
    for (int i = 0; i < draws; ++i) ++n[w.select(rng)];
    EXPECT_LT(n[0], 10);
    EXPECT_NEAR(n[1], draws * 1 / 7, 500);
    EXPECT_NEAR(n[2], draws * 2 / 7, 600);
    EXPECT_NEAR(n[3], draws * 4 / 7, 700);
}

TEST(Roulette, EqualFitnessIsUniform) {
    const std::vector<double> f(5, 0.7);
    RouletteWheel w;
    w.prepare(f);
    Rng rng(4);
    std::vector<int> n(5, 0);
    for (int i = 0; i < 50000; ++i) ++n[w.select(rng)];
    for (int c : n) EXPECT_NEAR(c, 10000, 450);
}

}  // namespace
}  // namespace shapevo
