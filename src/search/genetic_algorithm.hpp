// GeneticAlgorithm: ShapeGenetics Algorithm 1 on one population. Initial individuals are grown
// to a random length; each generation keeps the elite, then fills the rest in pairs: parent 1 by
// k-tournament, parent 2 by roulette; with probability `mutation` both are mutated (grow / cut /
// alter by their weights), otherwise crossed over (Algorithm 2, with retries).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "genome/operators.hpp"
#include "run/settings.hpp"
#include "search/evaluator.hpp"
#include "search/population.hpp"
#include "search/selection.hpp"

namespace shapevo {

struct GenerationStats {
    std::uint32_t generation = 0;
    double seconds = 0;
    std::uint64_t evaluations = 0;  ///< cumulative fitness evaluations
    double best = 0, mean = 0, std = 0;
};

class GeneticAlgorithm {
public:
    GeneticAlgorithm(const Grammar& g, const GaSettings& settings, const GenomeLimits& limits, std::uint64_t seed);

    /// Generation 1: grow and evaluate the initial population.
    void initialize(Evaluator& evaluator);
    /// Breed and evaluate the next generation.
    void step(Evaluator& evaluator);
    /// Continue from a saved state (a checkpoint): population with fitness, RNG, counters.
    void restore(const Population& pop, const std::array<std::uint64_t, 4>& rng, std::uint32_t generation,
                 std::uint64_t evaluations);

    const Population& population() const { return pop_; }
    Population& population() { return pop_; }
    std::uint32_t generation() const { return generation_; }
    std::uint64_t evaluations() const { return evaluations_; }
    /// best, mean, std of the current population (seconds and generation filled by the caller).
    GenerationStats stats() const;
    Rng& rng() { return rng_; }

private:
    void mutate(Chromosome& c);

    const Grammar& grammar_;
    GaSettings settings_;
    GenomeLimits limits_;
    Rng rng_;
    Population pop_, next_;
    Chromosome scratchChild_;  ///< second child of an odd last pair, discarded
    std::vector<std::size_t> order_;
    RouletteWheel wheel_;
    GenomeScratch scratch_;
    std::uint32_t generation_ = 0;
    std::uint64_t evaluations_ = 0;
};

}  // namespace shapevo
