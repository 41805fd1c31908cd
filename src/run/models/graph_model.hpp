// The graph-derivation family's LoadedModel (.yml, .yaml): a 2D graph grammar (graph/
// read_graph_grammar.hpp) with the run's [graph] limits, its genome GraphFamily, its models
// written as the original's SVG or as PNG. A file with no step limit of its own and no
// graph.max_steps derives at most kDefaultGraphSampleSteps (1,000) steps, as `sample` does.
#pragma once
#include <memory>
#include <string>

#include "run/models/loaded_model.hpp"

namespace shapevo {

/// From `text` (null: read `path`). @throw InputError for a bad grammar file.
std::unique_ptr<LoadedModel> loadGraphModel(const RunSettings& s, const std::string* text, const std::string& path);

/// The margin around a drawing's vertices in best.svg, best.png and exports (model units).
inline constexpr double kGraphModelMargin = 0.5;

}  // namespace shapevo
