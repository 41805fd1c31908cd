// Population diversity: how many different models a population holds, counted exactly (chromosomes
// compared word for word, not by hash alone): distinct genomes, distinct structures (the same
// genes with their parameters ignored: rule ids and child offsets only), and chromosome lengths.
// Structures need a tree's gene layout: for a family without a tree grammar only genomes and
// lengths are counted (structuresCounted false).
// For search.diagnostics (docs/search-diagnosis.md): once per generation, not on the hot path.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "genome/genome_family.hpp"
#include "search/population.hpp"

namespace shapevo {

struct Diversity {
    std::size_t distinctGenomes = 0;     ///< different chromosomes
    std::size_t distinctStructures = 0;  ///< different chromosomes once every parameter is set to 0
    bool structuresCounted = false;      ///< false for a family without a tree grammar (distinctStructures 0)
    double meanGenes = 0;
    std::uint32_t maxGenes = 0;
};

struct DiversityScratch {
    std::vector<std::vector<std::uint32_t>> structures;  ///< each individual's words, parameters zeroed
    std::vector<std::size_t> order;
};

Diversity measureDiversity(const GenomeFamily& family, const Population& pop, DiversityScratch& scratch);

}  // namespace shapevo
