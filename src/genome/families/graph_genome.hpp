// Graph genome: a 2D graph-grammar derivation's decisions as chromosome words. Layout:
//   word 0      kGraphGenomeTag
//   words 1, 2  the root seed (low, high): every decision no override names is drawn from it,
//               down the lineage (graph/keyed_draws.hpp)
//   then        overrides, 4 words each (key low, key high, word low, word high), keys strictly
//               ascending: a decision's value, or (an event's salt key) an event's own seed
// genes = 1 + overrides. A genome is valid when it has this shape and at most maxGenes genes; any
// values are valid, so every operator's output is valid by construction.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "genome/chromosome.hpp"
#include "graph/keyed_draws.hpp"

namespace shapevo {

inline constexpr std::uint32_t kGraphGenomeTag = 0x31475247;  // "GRG1"
inline constexpr std::size_t kGraphGenomeHeader = 3;

inline std::uint64_t graphGenomeSeed(const Chromosome& c) { return std::uint64_t(c.words[1]) | std::uint64_t(c.words[2]) << 32; }
inline std::span<const std::uint32_t> graphOverrides(const Chromosome& c) {
    return std::span<const std::uint32_t>(c.words).subspan(kGraphGenomeHeader);
}
inline std::size_t graphOverrideCount(const Chromosome& c) { return (c.words.size() - kGraphGenomeHeader) / graph::kOverrideWords; }

/// `c` becomes the genome of seed `seed` with no override.
void makeGraphGenome(Chromosome& c, std::uint64_t seed);
/// Empty if `c` is a valid graph genome of at most `maxGenes` genes, else what is wrong first.
std::string checkGraphGenome(const Chromosome& c, std::uint32_t maxGenes);
/// Give `key` the word `word` (replacing its override, or inserting one in key order).
void setGraphOverride(Chromosome& c, std::uint64_t key, std::uint64_t word);
/// Remove override `i`.
void removeGraphOverride(Chromosome& c, std::size_t i);

}  // namespace shapevo
