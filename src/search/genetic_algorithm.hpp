// GeneticAlgorithm: ShapeGenetics Algorithm 1 on one population. Initial individuals are grown
// to a random length; each generation keeps the elite, then fills the rest in pairs: parent 1 by
// k-tournament, parent 2 by roulette; with probability `mutation` both are mutated (grow / cut /
// alter by their weights), otherwise crossed over (Algorithm 2, with retries). Any model family:
// the operators are the family's (genome/genome_family.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "genome/genome_family.hpp"
#include "search/operator_outcomes.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"
#include "search/selection.hpp"

namespace shapevo {

class GeneticAlgorithm final : public SearchMethod {
public:
    /// Breeds `family`'s genomes with its operators within `limits`.
    GeneticAlgorithm(const GenomeFamily& family, const PopulationSettings& population, const GaSettings& settings,
                     const GenomeLimits& limits, std::uint64_t seed);

    /// Generation 1: grow and evaluate the initial population.
    void initialize(Evaluator& evaluator) override;
    /// Breed and evaluate the next generation.
    void step(Evaluator& evaluator) override;
    const OperatorOutcomes* operatorOutcomes() const override { return &outcomes_; }

private:
    std::unique_ptr<GenomeOperators> ops_;
    PopulationSettings population_;
    GaSettings settings_;
    Population next_;
    Chromosome scratchChild_;  ///< second child of an odd last pair, discarded
    std::vector<std::size_t> order_;
    RouletteWheel wheel_;
    // what made each child of this generation and its parent's fitness (crossover: the better
    // parent's), to count outcomes once the children are scored; which individuals were picked
    std::vector<OperatorOutcomes::Op> childOp_;
    std::vector<double> parentFitness_;
    std::vector<std::uint8_t> picked_;
    OperatorOutcomes outcomes_;
};

}  // namespace shapevo
