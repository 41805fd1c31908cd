// Genome files (.genome): one chromosome as bytes, so a best model can be re-derived, scored or
// exported later. Layout (little endian): "SVGENOME" magic, u32 version = 1, u32 genes,
// u32 words, u64 FNV-1a hash of the grammar text, then the words. Reading validates the
// chromosome against the grammar.
#pragma once
#include <string>

#include "genome/chromosome.hpp"

namespace shapevo {

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t h = 1469598103934665603ULL);
void writeGenome(const Grammar& g, const Chromosome& c, const std::string& path);
/// @throw InputError naming the file if it is unreadable, truncated, for another grammar or invalid.
Chromosome readGenome(const Grammar& g, const GenomeLimits& limits, const std::string& path);

}  // namespace shapevo
