// Parent selection (ShapeGenetics §6): k-tournament and roulette wheel. The roulette shifts
// fitness by the generation's worst value so negative fitness works (as the original code did).
#pragma once
#include <span>
#include <vector>

#include "genome/random.hpp"

namespace shapevo {

/// The fittest of k individuals drawn uniformly with replacement; ties keep the first drawn.
std::size_t tournamentSelect(std::span<const double> fitness, std::uint32_t k, Rng& rng);

/// Roulette wheel over fitness - worst (+ a tiny floor so every individual has a chance).
class RouletteWheel {
public:
    void prepare(std::span<const double> fitness);
    std::size_t select(Rng& rng) const;

private:
    std::vector<double> cumulative_;
};

}  // namespace shapevo
