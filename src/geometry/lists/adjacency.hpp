// unify / adjacency merge (PCGR §4.1, Fig 6): the components of flat scopes under shared-edge
// adjacency, by union-find. Components are a Grouping (grouping.hpp): in order of first
// appearance, members in list order. Deterministic; allocation-free once warm.
//
// A scope's edges are the 4 sides of its x-y rectangle through its origin (for a flat scope,
// size.z = 0, the shape itself; a volume counts by that mid-section). Two scopes are adjacent when
// an edge of one and an edge of the other share a segment: both longer than `tolerance`, each
// one's end points within `tolerance` (world distance) of the other's line, and their overlap
// along the edge of the earlier scope in the list longer than `tolerance`. So tiles of one grid
// that share a side, and the corner tiles of two facades meeting at a box's edge, are adjacent;
// tiles that touch only at a corner are not. Edges are paired by a sort-and-sweep over their
// boxes (grown by the tolerance), which finds every pair the plain all-pairs test finds.
#pragma once
#include <span>

#include <glm/vec3.hpp>

#include "geometry/lists/grouping.hpp"
#include "geometry/lists/list_workspace.hpp"
#include "geometry/pieces.hpp"

namespace shapevo::lists {

/// The adjacency test of two edges (a0-a1 and b0-b1), as above.
bool edgesShareSegment(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& b0, const glm::dvec3& b1, double tolerance);

/// The 4 edges of a scope's x-y rectangle: end points (corners[e], corners[(e + 1) % 4]).
void rectangleCorners(const Scope& s, glm::dvec3 (&corners)[4]);

/// Components of `scopes` under edge adjacency; `out.groupOf[i]` is scope i's component.
void unifyAdjacent(std::span<const Scope> scopes, double tolerance, Grouping& out, ListWorkspace& ws);

}  // namespace shapevo::lists
