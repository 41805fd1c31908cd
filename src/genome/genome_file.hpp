// Genome files (.genome): one chromosome as bytes, so a best model can be re-derived, scored or
// exported later. Layout (little endian): "SVGENOME" magic, u32 version = 2, u32 genes,
// u32 words, u32 reserved, u64 XXH3-64 of the grammar text (GenomeFamily::sourceText,
// base/hash.hpp), then the words. Any model family: the words are the family's genome.
// Version 1 files (an FNV-like grammar hash) are refused, naming both versions. Reading
// validates the chromosome with the family's check(); writing is atomic (base/atomic_write.hpp).
#pragma once
#include <cstdint>
#include <string>

#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"

namespace shapevo {

inline constexpr std::uint32_t kGenomeFileVersion = 2;

void writeGenome(const GenomeFamily& family, const Chromosome& c, const std::string& path);
/// @throw InputError naming the file if it is unreadable, truncated, for another grammar or invalid.
/// `grammarPath`: the file `family` was read from, for the message about another grammar.
Chromosome readGenome(const GenomeFamily& family, const std::string& grammarPath, const GenomeLimits& limits,
                      const std::string& path);

}  // namespace shapevo
