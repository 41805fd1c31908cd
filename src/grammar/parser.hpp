// Parser: reads a .grammar file into a checked Grammar, or throws InputError at file:line:column.
#pragma once
#include <string>

#include "grammar/grammar.hpp"

namespace shapevo {

/// Parse grammar text; `path` is only used in error messages and stored in Grammar::path.
Grammar parseGrammar(const std::string& text, const std::string& path);
/// Read and parse a grammar file.
Grammar loadGrammar(const std::string& path);

}  // namespace shapevo
