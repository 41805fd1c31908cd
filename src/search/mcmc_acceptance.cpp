// Acceptance rules of the RJMCMC baseline, in log space where ratios could overflow.
#include "search/mcmc_acceptance.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo {

double acceptanceFromLog(double logRatio) {
    if (std::isnan(logRatio)) return 0.0;
    return logRatio >= 0 ? 1.0 : std::exp(logRatio);
}

double jumpLogRatio(double f, double f2, double temperature, double weightBefore, double weightAfter) {
    return (f2 - f) / temperature + std::log(weightBefore) - std::log(weightAfter);
}

double swapAcceptance(double fi, double fj, double ti, double tj) {
    return acceptanceFromLog((fj - fi) * (1.0 / ti - 1.0 / tj));
}

double delayedRejectionAcceptance(double f, double f1, double f2, double fStar, double temperature, double wx, double w1) {
    const double firstForward = acceptanceFromLog(jumpLogRatio(f, f1, temperature, wx, w1));
    const double firstReverse = acceptanceFromLog(jumpLogRatio(f2, fStar, temperature, w1, wx));
    if (firstForward >= 1.0 || firstReverse >= 1.0) return 0.0;
    const double logRatio = jumpLogRatio(f, f2, temperature, wx, w1) + std::log1p(-firstReverse) - std::log1p(-firstForward);
    return acceptanceFromLog(logRatio);
}

double chainTemperature(std::uint32_t index, std::uint32_t chains, std::uint32_t generation, double coldest, double ratio,
                        double annealing, std::uint32_t interval) {
    const double position = chains > 1 ? double(index) / double(chains - 1) : 0.0;
    const double cooling = double((std::max(generation, 1u) - 1) / std::max(interval, 1u));
    // floor: a long anneal must not reach 0 (0/0 would reject even moves that change nothing)
    return std::max(coldest * std::pow(ratio, position) / std::pow(annealing, cooling), 1e-300);
}

}  // namespace shapevo
