// appendArcSegments: one SVG elliptical arc command (A/a, endpoint form) as the segments SVG
// renderers draw, after the SVG 1.1 implementation notes (appendix F.6): equal endpoints draw
// nothing; a zero radius draws a straight line; negative radii count by their size; radii too
// small to reach the endpoint are scaled up (keeping their ratio) until they just do; otherwise
// the flags pick one of the four arcs and it is cut into at most four cubic Béziers of at most 90
// degrees each. Each cubic starts and ends exactly on the ellipse (its last end is `to` itself);
// in between it leaves the ellipse by at most 2.7e-4 of the larger radius. Plain cubics, so the
// PNG painter and an exact rasterizer read arcs like any other curve.
#pragma once
#include <vector>

#include "graph/path_data.hpp"

namespace shapevo::graph {

struct EllipticalArc {
    Vec2 from;                        ///< the current point: where the arc starts
    double rx = 0, ry = 0;            ///< the radii in user units
    double xAxisRotationDegrees = 0;  ///< the ellipse's x axis against the user x axis (y down: clockwise)
    bool largeArc = false;            ///< the arc of more than 180 degrees
    bool sweep = false;               ///< true: through growing angles (clockwise on the y-down screen)
    Vec2 to;                          ///< the end point, absolute
};

/// Appends the arc to `out` (nothing, one Line, or one to four Cubic segments; no Move).
void appendArcSegments(const EllipticalArc& arc, std::vector<PathSegment>& out);

}  // namespace shapevo::graph
