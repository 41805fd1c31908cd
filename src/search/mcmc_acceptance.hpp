// Acceptance rules of the RJMCMC baseline (Talton et al. 2011 as outlined in ShapeGenetics §7),
// as pure functions so tests can check them against hand computations. The target of a chain at
// temperature T is prior(x) * exp(f(x) / T); moves propose from the prior, so the prior cancels:
//   diffusion (alter = redraw one gene's parameters from its prior):  min(1, exp((f' - f) / T))
//   jump (cut + regrow below gene v, v picked with weight w(v)/W):     min(1, exp((f' - f) / T) * W(x) / W(x'))
//   parallel-tempering swap of the states of chains i, j:              min(1, exp((f_j - f_i) (1/T_i - 1/T_j)))
//   delayed rejection, second stage after a rejected jump x -> y1, proposing y2 = y1 with one
//   paired gene re-drawn (its reverse path runs through y1* = x with that gene's new values):
//     min(1, exp((f2 - f) / T) * W(x)/W(y1) * (1 - a1(y2, y1*)) / (1 - a1(x, y1)))
//   (Tierney & Mira 1999; Green & Mira 2001; derivation in docs/search-methods.md).
#pragma once
#include <cstdint>

namespace shapevo {

/// min(1, exp(logRatio)); 0 for NaN or -inf.
double acceptanceFromLog(double logRatio);

/// log of the Metropolis-Hastings ratio of a jump from fitness f to f2 (weights W(x), W(x')).
double jumpLogRatio(double f, double f2, double temperature, double weightBefore, double weightAfter);

/// Probability of swapping the states of two chains (parallel tempering).
double swapAcceptance(double fi, double fj, double ti, double tj);

/// Second-stage acceptance of delayed rejection (see the top of this file): f = f(x), f1 = f(y1),
/// f2 = f(y2), fStar = f(y1*), wx = W(x), w1 = W(y1) (= W(y2)).
double delayedRejectionAcceptance(double f, double f1, double f2, double fStar, double temperature, double wx, double w1);

/// Temperature of chain `index` of `chains` at generation `generation` (1-based): a geometric
/// ladder from `coldest` to coldest * ratio, all divided by annealing^floor((generation-1)/interval).
double chainTemperature(std::uint32_t index, std::uint32_t chains, std::uint32_t generation, double coldest, double ratio,
                        double annealing, std::uint32_t interval);

}  // namespace shapevo
