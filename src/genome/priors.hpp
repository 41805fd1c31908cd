// Priors: drawing a parameter value from its prior, and testing that a value lies in its support.
#pragma once
#include "genome/random.hpp"
#include "grammar/grammar.hpp"

namespace shapevo {

float drawFromPrior(const Grammar& g, const Prior& p, Rng& rng);
bool inSupport(const Grammar& g, const Prior& p, float v);

}  // namespace shapevo
