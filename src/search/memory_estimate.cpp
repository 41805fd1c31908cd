// The memory estimate of memory_estimate.hpp: the method table gives the copies, the tree grammar
// (if the family has one) the largest gene.
#include "search/memory_estimate.hpp"

#include <algorithm>

#include "search/search_methods.hpp"

namespace shapevo {

MemoryEstimate searchMemoryEstimate(const GenomeFamily& family, const SearchSettings& search,
                                    const PopulationSettings& population, const GenomeLimits& limits) {
    MemoryEstimate e;
    const SearchMethodEntry* method = findSearchMethod(search.method);
    e.copies = (method ? method->populationCopies : 2u) + 2u;  // + a checkpoint's copy and its encoding
    if (const Grammar* g = family.treeGrammar())
        for (const Rule& r : g->rules) e.largestGeneWords = std::max(e.largestGeneWords, r.geneWords());
    else
        e.largestGeneWords = family.largestGeneWords();  // a family without a tree says it
    const double perIndividual = double(sizeof(Chromosome) + sizeof(double)) +
                                 double(limits.maxGenes) * 4.0 * double(e.largestGeneWords);
    e.bytes = double(population.population) * double(e.copies) * perIndividual;
    e.formula = "population " + std::to_string(population.population) + " x " + std::to_string(e.copies) + " copies x (" +
                std::to_string(sizeof(Chromosome) + sizeof(double)) + " + max_genes " + std::to_string(limits.maxGenes) +
                " x 4 x " + std::to_string(e.largestGeneWords) + " words of the largest gene) bytes";
    return e;
}

}  // namespace shapevo
