// Memory estimate of one island's search: what its populations take when every chromosome is
// as long as the genome limits allow, so that a run whose needs cannot be met is refused before
// it starts (run/memory_check.hpp) instead of failing with std::bad_alloc hours later.
// Promise: the estimate is the documented formula below, nothing measured:
//   bytes = population x (copies + 2) x (sizeof(Chromosome) + 8 + max_genes x 4 x W)
// W: 32-bit words of the largest gene: the tree grammar's largest gene for a family with one,
// 1 for a family without (its chromosome's words, one per gene); copies: whole populations the method keeps
// (SearchMethodEntry::populationCopies: GA and SMC 2, RJMCMC 4); + 2: a checkpoint's copy of the
// population and its encoding.
#pragma once
#include <cstdint>
#include <string>

#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "search/population_settings.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

struct MemoryEstimate {
    double bytes = 0;               ///< the formula's value (a double: no overflow)
    std::uint32_t copies = 0;       ///< populations counted, the checkpoint's included
    std::uint32_t largestGeneWords = 0;
    /// The formula with its numbers, e.g. "population 200 x 4 copies x (40 + max_genes 100 x 4 x 12 words) bytes".
    std::string formula;
};

/// The estimate for one island running `search.method` (a name in search_methods.cpp's table)
/// on `family`'s genomes.
MemoryEstimate searchMemoryEstimate(const GenomeFamily& family, const SearchSettings& search,
                                    const PopulationSettings& population, const GenomeLimits& limits);

}  // namespace shapevo
