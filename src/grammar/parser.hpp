// Parser: reads a .grammar file into a checked Grammar, or throws InputError at file:line:column.
#pragma once
#include <map>
#include <string>

#include "grammar/grammar.hpp"

namespace shapevo {

/// Values that replace attrs' definitions (a config's [grammar.attr] table, --set
/// grammar.attr.NAME=V). Naming an attr the grammar does not define is an error.
using AttrOverrides = std::map<std::string, double>;

/// Parse grammar text; `path` is only used in error messages and stored in Grammar::path.
Grammar parseGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides = {});
/// Read and parse a grammar file.
Grammar loadGrammar(const std::string& path, const AttrOverrides& overrides = {});

}  // namespace shapevo
