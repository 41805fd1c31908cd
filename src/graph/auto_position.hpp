// autoPosition: where a step puts a new vertex (graph-grammar README, section 2.6) — the daughter
// graph's drawing carried onto the matched host elements: rotated by the angle between the mother
// graph and its image (the first directed mother edge, or else least-squares lines as the original
// fits them: y on x, or x on y when σy/σx > 2, undirected), scaled per axis by host extent over
// mother extent after rotation (1 where an extent is 0), placed at the host barycentre.
#pragma once
#include <vector>

#include "graph/graph_grammar.hpp"
#include "graph/host_graph.hpp"

namespace shapevo::graph {

/// The frame one application carries daughter positions with.
struct PlacementFrame {
    Vec2 daughterCentre, hostCentre;
    double angle = 0;  // radians, counter-clockwise
    Vec2 scale{1, 1};
    Vec2 place(Vec2 daughterPosition) const;
};

/// Buffers placementFrame reuses from call to call.
struct PlacementScratch {
    std::vector<Vec2> daughter, host, mother, images;
};

/// `vertexImages`/`edgeImages`/`swapped`: the match (per mother vertex / edge).
PlacementFrame placementFrame(const Production& production, const ProductionOption& option, const HostGraph& graph,
                              const ElementId* vertexImages, const ElementId* edgeImages, const std::uint8_t* swapped,
                              PlacementScratch& scratch);

/// The angle (radians, in (-π/2, π/2]) of the original's least-squares line through `points`:
/// y on x, or x on y when σy/σx > 2; 0 for fewer than two distinct points.
double regressionAngle(const std::vector<Vec2>& points);

}  // namespace shapevo::graph
