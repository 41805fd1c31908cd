// validateChromosome: checks every invariant of a packed derivation tree; used by the property
// tests, by the checkpoint reader and by migration (untrusted bytes).
#pragma once
#include <string>

#include "genome/chromosome.hpp"

namespace shapevo {

/// Empty string if `c` is a valid derivation of `g` within `limits`, else what is wrong first.
std::string validateChromosome(const Grammar& g, const Chromosome& c, const GenomeLimits& limits);

}  // namespace shapevo
