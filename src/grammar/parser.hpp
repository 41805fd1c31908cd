// Grammar front ends: a .grammar file (parser.cpp) or a CastleMaker .rule file (crl/, front_end.cpp)
// into a checked Grammar, or an InputError at file:line:column.
#pragma once
#include <map>
#include <string>

#include "grammar/grammar.hpp"

namespace shapevo {

/// Values that replace attrs' definitions (a config's [grammar.attr] table, --set
/// grammar.attr.NAME=V). Naming an attr the grammar does not define is an error.
using AttrOverrides = std::map<std::string, double>;

/// Parse .grammar text (the shapevo language); `path` names it in error messages, is stored in
/// Grammar::path, and its folder is where `mesh` and `texture` files are found.
Grammar parseShapeGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides = {});

/// Parse grammar text with the front end its path's extension names: `.rule` is a CastleMaker
/// rule file (grammar/crl/), anything else the shapevo language.
Grammar parseGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides = {});
/// Read and parse a grammar file (either front end).
Grammar loadGrammar(const std::string& path, const AttrOverrides& overrides = {});
/// The shapevo-language text a rule file compiles into (what `shapevo translate` prints), after
/// the same checks loadGrammar makes.
std::string translateRuleFile(const std::string& path, const AttrOverrides& overrides = {});
/// True if `path` names a CastleMaker rule file (ends in .rule).
bool isRuleFile(const std::string& path);

}  // namespace shapevo
