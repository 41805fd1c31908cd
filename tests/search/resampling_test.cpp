// Multinomial resampling draws each particle in proportion to exp(log weight), whatever the
// offset of the log weights (they are shifted by their maximum), and never picks a zero weight.
#include <gtest/gtest.h>

#include <cmath>

#include "search/resampling.hpp"

namespace shapevo {
namespace {

TEST(Resampling, DrawCountsFollowTheWeights) {
    // weights 1 : 2 : 3 : 4 (log form, offset by 1000 to check the shift)
    const std::vector<double> logW{1000 + std::log(1.0), 1000 + std::log(2.0), 1000 + std::log(3.0), 1000 + std::log(4.0)};
    MultinomialResampler resampler;
    Rng rng(17);
    std::vector<std::size_t> out;
    std::array<double, 4> counts{};
    const int rounds = 20000;  // 80,000 draws
    for (int r = 0; r < rounds; ++r) {
        resampler.resample(logW, rng, out);
        ASSERT_EQ(out.size(), 4u);
        for (std::size_t i : out) counts[i] += 1;
    }
    const double draws = 4.0 * rounds;
    double chi2 = 0;
    for (int i = 0; i < 4; ++i) {
        const double expected = draws * (i + 1) / 10.0;
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    EXPECT_LT(chi2, 16.3) << "chi-square, 3 degrees of freedom, p = 0.001";
}

TEST(Resampling, ZeroWeightIsNeverDrawn) {
    const std::vector<double> logW{0.0, -INFINITY, 0.0};
    MultinomialResampler resampler;
    Rng rng(1);
    std::vector<std::size_t> out;
    for (int r = 0; r < 1000; ++r) {
        resampler.resample(logW, rng, out);
        for (std::size_t i : out) ASSERT_NE(i, 1u);
    }
}

TEST(Resampling, OneOverwhelmingWeightTakesEverySlot) {
    const std::vector<double> logW{0.0, 800.0, 0.0, 5.0};
    MultinomialResampler resampler;
    Rng rng(4);
    std::vector<std::size_t> out;
    resampler.resample(logW, rng, out);
    for (std::size_t i : out) EXPECT_EQ(i, 1u);
}

}  // namespace
}  // namespace shapevo
