// The Graphviz DOT text of a GraphDiagram (grammar/pcg/graph_diagram.hpp) in PCGR's notation, what
// `shapevo graph -o OUT.dot` writes and what report/graphviz_render.hpp lays out for .svg and .png.
// Each node is a rounded box (an HTML-like table) with its input ports on top, its title — "N
// name" with N its topological number counted from 1 (§3.4) and " *" after the name of a loop
// node (Fig 3) — and detail line in the middle, and its output ports below: single ports round
// (○), collective ports square (□), blocked ports filled (●, ■), gates framed thick; a port's name
// is shown unless it is its side's only port and is called in / out; the start node's box is
// bold. Edges run from port to port (or from the node itself): cyclic edges (§3.5) dashed and left
// out of the layout's ranking, as the sort leaves them out; inline calls blue; blocked edges grey
// with a bar. A legend names what is drawn. The same diagram gives the same text.
#pragma once
#include <string>

#include "grammar/pcg/graph_diagram.hpp"

namespace shapevo {

std::string diagramDot(const pcg::GraphDiagram& diagram);

/// The title line of node `node` as drawn: "3 Branch *".
std::string diagramNodeTitle(const pcg::DiagramNode& node);

}  // namespace shapevo
