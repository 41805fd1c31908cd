// populationStats: best, mean and population standard deviation of the fitness values.
#include "search/generation_stats.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo {

GenerationStats populationStats(const Population& pop, std::uint32_t generation, std::uint64_t evaluations) {
    GenerationStats s;
    s.generation = generation;
    s.evaluations = evaluations;
    const auto& f = pop.fitness;
    if (f.empty()) return s;
    s.best = *std::max_element(f.begin(), f.end());
    double sum = 0;
    for (double v : f) sum += v;
    s.mean = sum / double(f.size());
    double var = 0;
    for (double v : f) var += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(var / double(f.size()));
    return s;
}

}  // namespace shapevo
