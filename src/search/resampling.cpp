// Multinomial resampling: cumulative normalised weights and a binary search per draw.
#include "search/resampling.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo {

void MultinomialResampler::resample(const std::vector<double>& logWeights, Rng& rng, std::vector<std::size_t>& out) {
    const std::size_t n = logWeights.size();
    out.resize(n);
    if (n == 0) return;
    const double top = *std::max_element(logWeights.begin(), logWeights.end());
    cumulative_.resize(n);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += std::isfinite(logWeights[i] - top) ? std::exp(logWeights[i] - top) : 0.0;
        cumulative_[i] = sum;
    }
    for (std::size_t k = 0; k < n; ++k) {
        const double r = rng.uniform() * sum;
        const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), r);
        out[k] = std::min<std::size_t>(std::size_t(it - cumulative_.begin()), n - 1);
    }
}

}  // namespace shapevo
