// parsePathData: an SVG path's `d` (the subset graph grammars write: M L H V Q T C S Z, absolute
// and relative, implicit repeats, numbers with exponents and without separators where SVG allows
// them) into absolute segments in user units, for the PNG painter and any rasterizer of a
// Drawing. As SVG renderers do, the path is kept up to the first error and the rest dropped.
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
    bool complete = true;  ///< false: an error (an arc, an unknown command, a bad number) cut it there
};

PathData parsePathData(std::string_view d);

}  // namespace shapevo::graph
