// GenerationStats: one row of a fitness curve (generation, time, evaluations, best/mean/std),
// and the statistics of a population that every search method reports after each generation.
#pragma once
#include <cstdint>

#include "search/population.hpp"

namespace shapevo {

struct GenerationStats {
    std::uint32_t generation = 0;
    double seconds = 0;
    std::uint64_t evaluations = 0;  ///< cumulative fitness evaluations
    double best = 0, mean = 0, std = 0;
};

/// best, mean and std of `pop`'s fitness (seconds left 0 for the caller to fill).
GenerationStats populationStats(const Population& pop, std::uint32_t generation, std::uint64_t evaluations);

}  // namespace shapevo
