// Graphviz's C library (libgvc, libcgraph; Debian's libgraphviz-dev) as a function: DOT text in,
// the laid-out picture's bytes out, with no `dot` program and nothing printed. Plug-ins (the dot
// layout, the SVG and cairo PNG renderers) load on demand from Graphviz's installed config6a.
// What Graphviz says (errors and warnings) is caught, never written to stderr; every graph and
// layout is freed before returning, also on failure. The Graphviz context is made once per
// process and kept until exit (graphviz_render.cpp says why); calls are serialised.
#pragma once
#include <string>
#include <string_view>

namespace shapevo {

/// `dot` laid out with the dot layout and rendered as `format` ("svg" or "png").
/// @throw std::runtime_error with Graphviz's messages if it cannot read, lay out or render it.
std::string renderWithGraphviz(const std::string& dot, std::string_view format);

}  // namespace shapevo
