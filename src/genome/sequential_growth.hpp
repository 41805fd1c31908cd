// Sequential growth for SMC and SOSMC (ShapeGenetics §7, after Ritchie et al. 2015): a particle
// is a partial derivation whose undecided child positions (offset 0) are its "futures". Each call
// decides futures one at a time -- the first in chromosome order (SMC) or a uniformly random one
// (SOSMC) -- expressing it with its slot's grammar probability or marking it kRefused ("decided
// not expressed", never grown again), until a gene of a rule that emits geometry has been added
// or nothing is left undecided.
#pragma once
#include <vector>

#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

enum class GrowthOrder : std::uint8_t { Chromosome, Random };

/// Per rule id: 1 if the rule has a primitive statement (of any kind: box, cylinder, ...),
/// including one inside a `terminal` block.
std::vector<char> geometricRules(const Grammar& g);

/// Number of undecided (offset 0) child positions of `c`.
std::uint32_t undecidedChildren(const Grammar& g, const Chromosome& c);

/// Grow `c` by one geometric object as described above. An empty chromosome first gets its root
/// (plus mandatory children). A future whose rule would take `c` past limits.maxGenes is refused.
/// Returns true if any gene was added (the fitness may have changed).
bool growNextObject(const Grammar& g, Chromosome& c, Rng& rng, const GenomeLimits& limits, GrowthOrder order,
                    const std::vector<char>& geometric);

}  // namespace shapevo
