// The [graph] section: the limits of a 2D graph grammar derivation (graph/derive.hpp
// DeriveLimits) and the switches that fix the original tool's quirks, read by the graph stage
// itself. `sample FILE.yml` uses the same defaults (its --steps replaces max_steps).
#pragma once
#include "base/section_reader.hpp"
#include "graph/derive.hpp"

namespace shapevo::graph {

/// Read [graph] into `limits` (absent keys keep their defaults).
void readGraphSection(SectionReader& graph, DeriveLimits& limits);

}  // namespace shapevo::graph
