// ShapeOutline: a Shape's geometry in SVG user units (y down), as the raster for scoring
// (drawing_raster.hpp) reads it: a circle (centre, radius), or polylines — the shape's subpaths,
// each open or closed. Lines, rectangles and images are exact polylines; a path's quadratic and
// cubic Béziers are flattened so that every point of a curve lies within `tolerance` of the
// polyline (the polyline's vertices lie on the curve; at most kMaxCurvePieces pieces per curve,
// beyond which the tolerance is not kept), and the flattened path IS the shape from then on.
// outlineOf allocates nothing once `out` and the path scratch are warm.
#pragma once
#include <cstdint>
#include <vector>

#include "graph/drawing.hpp"
#include "graph/path_data.hpp"

namespace shapevo::graph {

/// The most straight pieces one quadratic or cubic Bézier becomes.
inline constexpr int kMaxCurvePieces = 1024;

struct Subpath {
    std::uint32_t begin = 0, end = 0;  ///< its points: ShapeOutline::points[begin, end)
    bool closed = false;               ///< Z (the closing segment from the last point to the first)
    bool drawn = false;                ///< it has a drawing command (L Q C Z), not only its M
};

struct ShapeOutline {
    enum class Form : std::uint8_t { None, Circle, Polylines };
    Form form = Form::None;  ///< None: nothing to paint (a circle of radius <= 0, an empty rect, no `d`)
    Vec2 centre;             ///< Circle (user units)
    double radius = 0;       ///< Circle (user units)
    std::vector<Vec2> points;
    std::vector<Subpath> subpaths;
};

/// A model point in SVG user units: x * kUserUnitsPerModelUnit, -(y * kUserUnitsPerModelUnit).
Vec2 userPoint(Vec2 model);

/// The outline of `s` into `out` (cleared first). Circle: centre and `r` (a CSS length). Line:
/// one open subpath end1 -> end2. Rect: one closed subpath (x, y), (x + w, y), (x + w, y + h),
/// (x, y + h) with x, y, w, h as the SVG writer writes them. Image: its rectangle's corners turned
/// by `rotation` degrees about its centre (SVG's rotate()), closed. Path: `d` parsed into
/// `pathScratch`, one subpath per M (a drawing command after Z starts one at the closed
/// subpath's first point), curves flattened to `tolerance` user units.
void outlineOf(const Shape& s, double tolerance, PathData& pathScratch, ShapeOutline& out);

/// Appends the flattened quadratic p0 (current point), c, e to `points`, not p0, ending exactly on e.
void flattenQuad(Vec2 p0, Vec2 c, Vec2 e, double tolerance, std::vector<Vec2>& points);
/// Appends the flattened cubic p0 (current point), c1, c2, e to `points`, not p0, ending exactly on e.
void flattenCubic(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 e, double tolerance, std::vector<Vec2>& points);

}  // namespace shapevo::graph
