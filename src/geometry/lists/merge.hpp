// merge (PCGR §4.1): several entities become one whose scope is the bounding box of the members'
// scopes, in the first member's frame: its axes are the first member's, its size and centre make
// the smallest such box holding every corner of every member (a flat member adds its 4 corners).
// Axes are taken orthonormal, as derive makes them. Computed in double, stored as Scope's floats;
// look is the first member's. k coplanar tiles of one grid merge into exactly their union
// rectangle (up to float rounding of the centre).
#pragma once
#include <span>

#include "geometry/pieces.hpp"

namespace shapevo::lists {

/// The merged scope of `members` (non-empty; an empty list gives a zero-size Scope at the origin).
Scope mergeScopes(std::span<const Scope> members);

/// The 8 corners of a scope (world points): origin + axes * (±size/2), x fastest.
void scopeCorners(const Scope& s, glm::dvec3 (&corners)[8]);

}  // namespace shapevo::lists
