// SearchMethod: the shared start from random growth.
#include "search/search_method.hpp"

#include "genome/operators.hpp"

namespace shapevo {

void SearchMethod::startFromRandomGrowth(const Grammar& g, const GenomeLimits& limits, std::uint32_t minGenes,
                                         std::uint32_t maxGenes, Evaluator& evaluator) {
    for (Chromosome& c : pop_.individuals) growRandomLength(g, c, rng_, limits, minGenes, maxGenes);
    evaluator.evaluate(pop_);
    evaluations_ += pop_.size();
    generation_ = 1;
}

}  // namespace shapevo
