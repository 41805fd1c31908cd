// readGraphGrammar: a 2D graph grammar YAML file (graph-grammar README, section 1) into a
// GraphGrammar, every expression compiled and every id checked. Bad input is one InputError
// naming the file, line and column, and the production and element where it applies.
#pragma once
#include <string>
#include <string_view>

#include "graph/graph_grammar.hpp"

namespace shapevo::graph {

GraphGrammar readGraphGrammar(const std::string& path);
/// True for a path read as a 2D graph grammar: .yml or .yaml (any case).
bool isGraphGrammarPath(const std::string& path);
/// The same from text already read (tests, fuzzing); `path` is used in messages only.
GraphGrammar parseGraphGrammar(std::string_view text, const std::string& path);

}  // namespace shapevo::graph
