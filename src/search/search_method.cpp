// SearchMethod: the shared start from random growth.
#include "search/search_method.hpp"

namespace shapevo {

void SearchMethod::startFromRandomGrowth(GenomeOperators& ops, std::uint32_t minGenes, std::uint32_t maxGenes,
                                         Evaluator& evaluator) {
    for (Chromosome& c : pop_.individuals) ops.randomGenome(c, rng_, minGenes, maxGenes);
    evaluator.evaluate(pop_);
    evaluations_ += pop_.size();
    generation_ = 1;
}

}  // namespace shapevo
