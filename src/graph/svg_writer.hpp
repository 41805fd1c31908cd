// drawingSvg: a Drawing as the original's exporter (svgwrite) writes it (graph-grammar README,
// section 4): 1 model unit = kUserUnitsPerModelUnit user units, y negated, the canvas (the
// vertices' box, grown by a margin) as viewBox, width and height; the preamble's filters in
// <defs>; each shape one element with its attributes sorted by name, numbers as Python's repr
// writes them, every value XML-escaped. The same Drawing gives the same bytes.
#pragma once
#include <span>
#include <string>

#include "graph/drawing.hpp"
#include "graph/graph_grammar.hpp"

namespace shapevo::graph {

/// The SVG document (no trailing newline, as the original). Filter primitive attribute names
/// get '_' -> '-' (one trailing '_' dropped); a filter tag or attribute name that is not an XML
/// name, or is an event handler (on...), is left out (the reader refuses them with a message).
std::string drawingSvg(const Drawing& drawing, std::span<const SvgFilter> filters, const DrawingCanvas& canvas);

}  // namespace shapevo::graph
