// Outline: what a primitive's silhouette is made of (score/image/silhouette_outline.hpp has the full
// definition of "covered" and the builder that makes outlines for a camera): pieces of points in
// 1/256-pixel fixed point, each piece covering the closed convex hull of its points. The kinds'
// outline code (shape/kinds/*.hpp, `outline`) appends pieces; these types and constants are what
// it may rely on without seeing the camera, with UnitShape, the convex polyhedra in a primitive's
// local coordinates that pieces are projected from (the builder's own, or a kind's OutlineScratch).
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "shape/primitive.hpp"

namespace shapevo {

struct FixedPoint {
    std::int32_t x, y;  ///< pixel coordinates * kSubpixels
    bool operator==(const FixedPoint&) const = default;
};
inline constexpr std::int64_t kSubpixels = 256;
/// Pixel coordinates -> fixed point, rounded to nearest, halves up (|x|, |y| well below 2^23;
/// exact: scaling by 256 and adding 0.5 round nothing in that range).
inline FixedPoint snapToFixed(double x, double y) {
    return {std::int32_t(std::floor(x * double(kSubpixels) + 0.5)), std::int32_t(std::floor(y * double(kSubpixels) + 0.5))};
}
inline constexpr double kGuardBand = 16384.0;
/// Levels of detail for rings: kRoundSides >> level corners, level 0 .. kRoundLevels - 1.
inline constexpr int kRoundLevels = 3;
/// Largest pixel radius (projectedRadius) drawn at level 1 and 2 (8 and 4 ring corners): left-out
/// corners stay within 1/4 pixel (0.0761 r and 0.293 r from the chords that replace them).
inline constexpr double kRingLevelRadius[kRoundLevels] = {INFINITY, 0.25 / 0.0761, 0.25 / 0.293};
/// The coarsest level whose radius limit (kRingLevelRadius, or a kind's own, e.g. kSphereLevelRadius) admits a ring
/// of `pixels` pixel radius.
inline int detailLevel(double pixels, const double (&limits)[kRoundLevels]) {
    int level = 0;
    while (level + 1 < kRoundLevels && pixels <= limits[level + 1]) ++level;
    return level;
}
static_assert(kRoundSides >= 3 && kRoundSides <= 32, "ring corners are kept in 32-bit masks");

/// Points [first, first + count) of an Outline. The first rings * ringSize of them are `rings`
/// rings of ringSize points each, in cyclic order around a convex polygon before snapping (a
/// hint a hull algorithm may use; it must not rely on it); the rest come in no order.
struct OutlinePiece {
    std::uint32_t first = 0, count = 0;
    std::uint16_t rings = 0, ringSize = 0;
};

/// A convex polyhedron in a primitive's local (u) coordinates, drawn as one piece (all of its
/// vertices; cut by the clip plane along its edges when needed).
struct UnitShape {
    std::vector<glm::dvec3> vertices;  ///< local (u) coordinates; rings first, then loose points
    std::vector<std::uint16_t> edges;  ///< pairs of vertex indices
    std::uint16_t rings = 0, ringSize = 0;
};

struct Outline {
    std::vector<FixedPoint> points;
    std::vector<OutlinePiece> pieces;
    void clear() {
        points.clear();
        pieces.clear();
    }
};

}  // namespace shapevo
