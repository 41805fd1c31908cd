// Multinomial resampling for SMC (Ritchie et al. 2015; "roulette wheel resampling" in the
// ShapeGenetics configs): n draws with replacement, each index chosen with probability
// exp(logWeight[i]) / sum_j exp(logWeight[j]). Weights are taken in log space and shifted by
// their maximum, so exp((f_new - f_old) / T) never overflows.
#pragma once
#include <vector>

#include "genome/random.hpp"

namespace shapevo {

class MultinomialResampler {
public:
    /// Draw logWeights.size() indices into `out` (one uniform per draw, in order).
    void resample(const std::vector<double>& logWeights, Rng& rng, std::vector<std::size_t>& out);

private:
    std::vector<double> cumulative_;
};

}  // namespace shapevo
