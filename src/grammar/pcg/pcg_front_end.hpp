// The `.pcg` graph file front end (grammars/pcg/README.md): what grammar/front_ends.cpp's table
// entry calls. A graph is translated into shapevo-language text with the `.pcg` place of every
// line (grammar/translation.hpp), so the shapevo parser's errors stay located in the user's file;
// its picture for `shapevo graph` is the graph itself, includes expanded, in PCGR's notation.
#pragma once
#include <string>

#include "grammar/pcg/graph_diagram.hpp"
#include "grammar/translation.hpp"

namespace shapevo::pcg {

/// The graph file `path` (its text given) in the shapevo language; Translation::files: every
/// included graph file, relative to the main file's folder. @throw InputError at file:line:column.
Translation translatePcg(const std::string& text, const std::string& path);

/// The graph file as a diagram, numbered (§3.4, §3.5). @throw InputError at file:line:column.
GraphDiagram pcgDiagram(const std::string& text, const std::string& path);

}  // namespace shapevo::pcg
