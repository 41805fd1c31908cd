// RandomSampling: the baseline every search method must beat — best of N random derivations.
// Each generation draws `population` fresh random genomes (the family's randomGenome, as a
// method's first generation does), scores them, and keeps the `population` best of the old and
// the new (ties: the older first), so the population's best is the best of every derivation drawn
// so far, with as many evaluations per generation as the GA makes. Any model family.
#pragma once
#include <memory>
#include <vector>

#include "genome/genome_family.hpp"
#include "search/population_settings.hpp"
#include "search/search_method.hpp"

namespace shapevo {

class RandomSampling final : public SearchMethod {
public:
    RandomSampling(const GenomeFamily& family, const PopulationSettings& population, const GenomeLimits& limits, std::uint64_t seed);
    void initialize(Evaluator& evaluator) override;
    void step(Evaluator& evaluator) override;

private:
    std::unique_ptr<GenomeOperators> ops_;
    PopulationSettings population_;
    Population next_, merged_;
    std::vector<std::size_t> order_;
};

}  // namespace shapevo
