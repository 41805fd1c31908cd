// makeSearchMethod: the one place that maps SearchMethodKind to a class (a switch, no registry).
#include "search/genetic_algorithm.hpp"
#include "search/rjmcmc.hpp"
#include "search/smc.hpp"

namespace shapevo {

std::unique_ptr<SearchMethod> makeSearchMethod(const SearchSettings& search, const GaSettings& ga, const Grammar& g,
                                               const GenomeLimits& limits, std::uint64_t seed) {
    switch (search.method) {
    case SearchMethodKind::Ga: return std::make_unique<GeneticAlgorithm>(g, ga, limits, seed);
    case SearchMethodKind::Smc:
        return std::make_unique<Smc>(g, search.smc, ga.population, limits, GrowthOrder::Chromosome, seed);
    case SearchMethodKind::Sosmc:
        return std::make_unique<Smc>(g, search.smc, ga.population, limits, GrowthOrder::Random, seed);
    case SearchMethodKind::Rjmcmc: return std::make_unique<Rjmcmc>(g, search.rjmcmc, ga, limits, seed);
    }
    return nullptr;
}

}  // namespace shapevo
