// Acceptance rules of the RJMCMC baseline against values computed by hand (Python, double
// precision): jump ratio with selection weights, tempering swaps, delayed rejection's second
// stage, and the temperature ladder with annealing.
#include <gtest/gtest.h>

#include <cmath>

#include "search/mcmc_acceptance.hpp"

namespace shapevo {
namespace {

TEST(McmcAcceptance, JumpRatioIncludesTheSelectionWeights) {
    // f 0 -> -0.1 at T = 0.1 is exp(-1); W(x) = 3, W(x') = 2 makes it 1.5 exp(-1)
    EXPECT_NEAR(acceptanceFromLog(jumpLogRatio(0.0, -0.1, 0.1, 3, 2)), 1.5 * std::exp(-1.0), 1e-12);
    EXPECT_EQ(acceptanceFromLog(jumpLogRatio(0.0, 0.5, 0.1, 1, 4)), 1.0);
    EXPECT_EQ(acceptanceFromLog(std::nan("")), 0.0);
}

TEST(McmcAcceptance, TemperingSwapFollowsTheProductOfBothTargets) {
    // exp((0.3 - 0.8) (1/0.5 - 1/2)) = 0.47236655274101
    EXPECT_NEAR(swapAcceptance(0.8, 0.3, 0.5, 2.0), 0.47236655274101, 1e-12);
    EXPECT_EQ(swapAcceptance(0.3, 0.8, 0.5, 2.0), 1.0) << "the better state always moves to the colder chain";
    EXPECT_EQ(swapAcceptance(0.1, 0.9, 1.0, 1.0), 1.0) << "equal temperatures: swapping changes nothing";
}

TEST(McmcAcceptance, DelayedRejectionSecondStageMatchesTheTierneyMiraFormula) {
    // min(1, e^{(f2-f)/T} W(x)/W(y1) (1 - a1(y2,y1*)) / (1 - a1(x,y1))), a1 the jump acceptance
    EXPECT_NEAR(delayedRejectionAcceptance(0, -1, 0.5, -0.2, 1, 1, 2), 0.0068988558983939284, 1e-12);
    EXPECT_NEAR(delayedRejectionAcceptance(0, -2, -0.1, -3, 1, 1, 1), 0.9888808148304232, 1e-12);
    EXPECT_EQ(delayedRejectionAcceptance(1.0, 0.2, 0.9, 1.5, 0.5, 3, 2), 0.0)
        << "if the reverse path's first stage would surely be accepted, the second stage never is";
}

TEST(McmcAcceptance, TemperatureLadderSpansTheRatioAndAnneals) {
    const double ratio = std::log(0.01) / std::log(0.7);
    EXPECT_NEAR(chainTemperature(0, 4, 1, 0.1, ratio, 1.1, 10), 0.1, 1e-15);
    EXPECT_NEAR(chainTemperature(3, 4, 1, 0.1, ratio, 1.1, 10), 0.1 * ratio, 1e-12);
    // a move accepted 70 % of the time by the hottest chain is accepted 1 % by the coldest
    const double d = -std::log(0.7) * chainTemperature(3, 4, 1, 0.1, ratio, 1.1, 10);
    EXPECT_NEAR(std::exp(-d / chainTemperature(0, 4, 1, 0.1, ratio, 1.1, 10)), 0.01, 1e-12);
    // chain 1 of 4 at generation 21 with interval 10: two annealing steps
    EXPECT_NEAR(chainTemperature(1, 4, 21, 0.1, 12.911, 1.1, 10), 0.1938807049101454, 1e-12);
    EXPECT_EQ(chainTemperature(1, 4, 20, 0.1, 12.911, 1.1, 10), chainTemperature(1, 4, 11, 0.1, 12.911, 1.1, 10));
    EXPECT_GT(chainTemperature(0, 1, 1u << 30, 1e-3, 1, 1.1, 1), 0.0) << "never reaches zero";
}

}  // namespace
}  // namespace shapevo
