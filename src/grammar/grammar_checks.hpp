// Whole-grammar checks run after parsing: recursion that can never end (a cycle of
// probability-1 child slots), and the mandatory-subtree sizes the genome operators need.
#pragma once
#include <functional>
#include <string>

#include "grammar/grammar.hpp"

namespace shapevo {

using GrammarFailure = std::function<void(const SourceLocation&, const std::string&)>;

/// Fills Grammar::mandatoryGenes / mandatoryWords; calls `fail` (which must throw) on an error.
void checkGrammar(Grammar& g, const GrammarFailure& fail);

}  // namespace shapevo
