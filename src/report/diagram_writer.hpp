// Writing a GraphDiagram (grammar/pcg/graph_diagram.hpp) to a file, what `shapevo graph` does: .dot
// as its DOT text (report/diagram_dot.hpp), .svg and .png laid out by Graphviz's library
// (report/graphviz_render.hpp). The picture is made before the file is opened and written
// atomically, never over an existing file.
#pragma once
#include <array>
#include <string>
#include <string_view>

#include "grammar/pcg/graph_diagram.hpp"

namespace shapevo {

/// What `shapevo graph -o` writes.
inline constexpr std::array<std::string_view, 3> kDiagramFormats{"dot", "svg", "png"};

/// `diagram` as `format` (one of kDiagramFormats) at `path`.
/// @throw InputError naming `path` if it exists or cannot be written; std::runtime_error if
/// Graphviz fails.
void writeDiagram(const pcg::GraphDiagram& diagram, std::string_view format, const std::string& path);

}  // namespace shapevo
