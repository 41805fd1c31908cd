// sampleGraphs: what `shapevo sample FILE.yml` does for a 2D graph grammar (graph-grammar README):
// derivations from the file's first host graph, each drawn as the original's exporter draws it,
// written as SVG (graph/svg_writer.hpp) or PNG (report/graph_picture.hpp). Promises: file k is
// the derivation of seed + k - 1, the same bytes on every machine; every option and output name
// is checked and every derivation made and drawn before anything is written, so bad input leaves
// no files behind; an existing file is never replaced. With --genome, each derivation is the one a
// genome of root seed seed + k - 1 makes (keyed decisions, as a run's genomes derive; its drawing
// differs from the seed's sequential one) and that genome is written too (G.genome, numbered like
// the drawings), for `evaluate`, `target G.genome --image` or a run's comparison.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

#include "graph/read_graph_grammar.hpp"
#include "run/sample_models.hpp"

namespace shapevo {

using graph::isGraphGrammarPath;

/// The margin `sample` adds around a graph grammar's vertices, in model units, when --margin is
/// not given (the shapes on the border stay whole; --margin 0 is the original's canvas).
inline constexpr double kDefaultGraphMargin = 0.5;

/// The steps `sample` allows a derivation when neither --steps nor the file's
/// options.max_derivations.all limits it (a grammar that never ends stops here, and says so).
inline constexpr std::int64_t kDefaultGraphSampleSteps = 1000;

/// Derives, draws and writes what `request` asks for; prints one line per file ("koch.yml seed
/// 1: 192 steps, 579 vertices, 579 edges (0 dangling), 1158 elements -> koch.svg").
/// @throw InputError for an option that only tree grammars take, a bad option value, an
/// existing output, a file that cannot be read or a derivation that fails.
void sampleGraphs(const SampleRequest& request, std::ostream& out);

}  // namespace shapevo
