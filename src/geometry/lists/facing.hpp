// facing, PCGR's "is oriented to" (§4.5, Fig 1, Fig 8): for each flat shape of list 1, whether
// some point of some street is in view of it, optionally unoccluded by the other shapes of list 1.
// Streets are segments (two world points); streetOfScope makes one of a street entity.
//
// A shape views from its origin c along its normal n (its scope's z axis). A street point p is in
// view when p != c and the angle between n and p - c is at most the tolerance (in [0°, 90°)).
// Without occlusion the answer is exact: the point of a segment with the smallest angle to n is an
// end or the one interior critical point of the angle along the segment, and it is tested.
// Unoccluded: a point in view counts only if the segment c-p enters no other shape of list 1 (its
// oriented box, a rectangle when flat; box_tree.hpp's rayBoxDistance, distance below |p - c|); the
// points tried are `samples` evenly spaced points of each segment (both ends included) and the
// smallest-angle point, so a street seen only through a gap narrower than the sample spacing can be
// missed. Deterministic; allocation-free once the tree has grown.
#pragma once
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "geometry/lists/box_tree.hpp"

namespace shapevo::lists {

struct StreetSegment {
    glm::dvec3 a{0.0}, b{0.0};
};

/// A street entity's segment: its scope's x extent through its origin (a road scope's centre line).
StreetSegment streetOfScope(const Scope& s);

struct FacingOptions {
    double toleranceDegrees = 45.0;  ///< in [0, 90)
    bool unoccluded = false;         ///< also require an unoccluded line of sight
    std::uint32_t samples = 33;      ///< street points tried per segment when unoccluded (at least 2)
};

/// out[i] (out.size() == shapes.size()) = 1 if shape i faces some street, else 0. `tree` is
/// rebuilt over `shapes` when options.unoccluded.
void facing(std::span<const Scope> shapes, std::span<const StreetSegment> streets, const FacingOptions& options,
            BoxTree& tree, std::span<std::uint8_t> out);

/// The cosine of the angle between `normal` (unit) and p(t) - c over the segment's smallest-angle
/// point, and that point's parameter t in [0, 1]; -2 if every point of the segment is c.
double bestViewCosine(const glm::dvec3& c, const glm::dvec3& normal, const StreetSegment& street, double& bestT);

}  // namespace shapevo::lists
