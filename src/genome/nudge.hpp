// Nudge: a small step of one parameter, for local refinement of continuous parameters (alter
// redraws a whole gene from its priors, which cannot fine-tune a gene such as the castle's that
// holds every size of the model). Pure genome operator: no derivation, no allocation.
#pragma once
#include "genome/chromosome.hpp"
#include "genome/random.hpp"

namespace shapevo {

/// Nudge: pick a gene with parameters uniformly, one of its floats uniformly, and move it:
/// uniform and normal priors by a normal step whose deviation is a fraction of the support's
/// width drawn log-uniformly in [0.003, 0.3] (coarse and fine steps alike), reflected back into
/// the support; integers by +-1 (inward at a bound); choices to another of their values.
/// The value always stays in the prior's support (inSupport). Returns false if no gene has a
/// parameter that can move (no parameters, or only single-valued supports).
bool nudge(const Grammar& g, Chromosome& c, Rng& rng);

}  // namespace shapevo
