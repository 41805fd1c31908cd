// Tournament and roulette selection.
#include "search/selection.hpp"

#include <algorithm>

namespace shapevo {

std::size_t tournamentSelect(std::span<const double> fitness, std::uint32_t k, Rng& rng) {
    std::size_t best = rng.below(std::uint32_t(fitness.size()));
    for (std::uint32_t i = 1; i < k; ++i) {
        const std::size_t c = rng.below(std::uint32_t(fitness.size()));
        if (fitness[c] > fitness[best]) best = c;
    }
    return best;
}

void RouletteWheel::prepare(std::span<const double> fitness) {
    const double worst = *std::min_element(fitness.begin(), fitness.end());
    const double best = *std::max_element(fitness.begin(), fitness.end());
    const double floor = std::max(1e-12, (best - worst) * 1e-6);
    cumulative_.resize(fitness.size());
    double sum = 0;
    for (std::size_t i = 0; i < fitness.size(); ++i) {
        sum += fitness[i] - worst + floor;
        cumulative_[i] = sum;
    }
}

std::size_t RouletteWheel::select(Rng& rng) const {
    const double r = rng.uniform() * cumulative_.back();
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), r);
    return std::min<std::size_t>(std::size_t(it - cumulative_.begin()), cumulative_.size() - 1);
}

}  // namespace shapevo
