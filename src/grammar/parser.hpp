// The shapevo grammar language's parser (parser.cpp and its parts): .grammar text into a checked
// Grammar, or an InputError at file:line:column. Which reader a file goes to is front_ends.hpp's.
#pragma once
#include <string>

#include "grammar/attr_overrides.hpp"
#include "grammar/grammar.hpp"

namespace shapevo {

/// Parse .grammar text (the shapevo language); `path` names it in error messages, is stored in
/// Grammar::path, and its folder is where `mesh` and `texture` files are found.
Grammar parseShapeGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides = {});

}  // namespace shapevo
