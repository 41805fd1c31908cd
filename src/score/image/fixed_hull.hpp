// FixedHull: the exact convex hull of one outline piece (snapped integer points), for the
// silhouette rasterizer. A piece that is one ring already forming a convex polygon that winds
// once (checked with integer orientation tests; repeated points and points along an edge are
// allowed: the usual case for silhouette loops, spheres and triangles) is its own hull. Otherwise Andrew's monotone chain with integer
// orientation tests; the points are put in x order by merging the piece's rings (each ring of a
// projected convex polygon is already two x-sorted chains) and a final insertion sort, which
// costs one pass when the rings kept their order and still sorts correctly when snapping broke it.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "score/image/silhouette_outline.hpp"

namespace shapevo {

/// Orientation of (o, a, b): > 0 counter-clockwise (in x-right, y-up terms), 0 collinear.
inline std::int64_t orientation(FixedPoint o, FixedPoint a, FixedPoint b) {
    return (std::int64_t(a.x) - o.x) * (std::int64_t(b.y) - o.y) - (std::int64_t(a.y) - o.y) * (std::int64_t(b.x) - o.x);
}

class FixedHull {
public:
    /// Hull vertices of points[piece.first .. + piece.count), counter-clockwise without repeated
    /// points, every turn left or straight (vertices along an edge may stay). Fewer than 3
    /// vertices: zero area. Valid until the next call.
    std::span<const FixedPoint> of(const FixedPoint* points, const OutlinePiece& piece);

private:
    std::vector<FixedPoint> sorted_, merged_, hull_;
};

}  // namespace shapevo
