// Uncontrolled derivations for `shapevo sample`: a derivation drawn from the grammar itself.
// Every sibling position of every slot of every expressed gene is decided once, independently,
// with its slot's `prob` (mandatory slots always), recursively until nothing is undecided; the
// alternative and the parameters come from their weights and priors. A size window
// [minGenes, maxGenes] is met by rejection: a derivation that would pass maxGenes is abandoned
// as soon as it does, one below minGenes is dropped, and the next is drawn from the same
// generator, so a kept derivation is an exact draw from the grammar conditioned on its size.
//
// The GA's own initial population (growRandomLength) and its grow mutation (operators.hpp)
// choose *how many* genes to grow and then pick positions by weight; they are not this.
#pragma once
#include <cstdint>

#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

/// `c` = one uncontrolled derivation (see above) with at most `maxGenes` genes. Returns false,
/// with `c` holding the partial derivation, if it would need more.
bool growUncontrolled(const Grammar& g, Chromosome& c, Rng& rng, std::uint32_t maxGenes);

struct SampleOutcome {
    bool found = false;
    std::uint32_t attempts = 0;  ///< derivations drawn, the kept one included
    std::uint32_t tooLarge = 0;  ///< of those, how many were abandoned at maxGenes
};

/// Whether some `optional` child slot can lead back to its own rule: a recursion that ends only
/// by chance (a CastleMaker rule file's recursive stochastic rule is one, castlemaker-crl.txt
/// §5.2), so that an uncontrolled derivation may grow without end.
bool hasOptionalRecursion(const Grammar& g);

/// Draw derivations with growUncontrolled until one has between minGenes and maxGenes genes,
/// at most `maxAttempts` of them. On success `c` is that derivation.
SampleOutcome sampleDerivation(const Grammar& g, Chromosome& c, Rng& rng, std::uint32_t minGenes,
                               std::uint32_t maxGenes, std::uint32_t maxAttempts);

}  // namespace shapevo
