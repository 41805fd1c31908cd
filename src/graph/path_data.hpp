// parsePathData: an SVG path's `d` (all of SVG 1.1's path data: M L H V Q T C S A Z, absolute
// and relative, implicit repeats, numbers with exponents and without separators where SVG allows
// them, arc flags without separators as in "a1 1 0 00 1 1") into absolute segments in user units,
// for the PNG painter and any rasterizer of a Drawing. An arc (A) becomes what SVG renderers draw
// (elliptical_arc.hpp): nothing, a Line, or one to four Cubic segments, so a reader of the
// segments meets no arc. As SVG renderers do, the path is kept up to the first error and the rest
// dropped.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "graph/value.hpp"

namespace shapevo::graph {

struct PathSegment {
    enum class Op : std::uint8_t { Move, Line, Quad, Cubic, Close };
    Op op = Op::Move;
    Vec2 p[3];  ///< Move/Line: p[0]; Quad: control p[0], end p[1]; Cubic: p[0], p[1], end p[2]
};

struct PathData {
    std::vector<PathSegment> segments;
    /// false: an error cut the path there (an unknown command, a missing or bad number or arc flag,
    /// a path not starting with M); the segments before it are kept
    bool complete = true;
};

PathData parsePathData(std::string_view d);
/// The same into `out` (cleared first): its capacity is reused, so a warm `out` allocates nothing.
void parsePathData(std::string_view d, PathData& out);

}  // namespace shapevo::graph
