// GenerationStats: one row of a fitness curve (generation, time, evaluations, best/mean/std, and
// the IoU of the best model), and the statistics of a population that every search method
// reports after each generation.
#pragma once
#include <cstdint>
#include <limits>

#include "search/population.hpp"

namespace shapevo {

struct GenerationStats {
    std::uint32_t generation = 0;
    double seconds = 0;
    std::uint64_t evaluations = 0;  ///< cumulative fitness evaluations
    double best = 0, mean = 0, std = 0;
    /// IoU (voxel or silhouette, 0..1) of the model whose fitness is `best`: derived data, measured
    /// by the run loop (run/island_loop.cpp), never by a search method; NaN where not measured.
    double iou = std::numeric_limits<double>::quiet_NaN();
};

/// best, mean and std of `pop`'s fitness (seconds left 0 and iou NaN for the caller to fill).
GenerationStats populationStats(const Population& pop, std::uint32_t generation, std::uint64_t evaluations);

}  // namespace shapevo
