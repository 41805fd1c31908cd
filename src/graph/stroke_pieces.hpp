// StrokePieces: the stroke region of a polyline outline (shape_outline.hpp) as a union of simple
// regions, each with an exact point test that is the same arithmetic wherever it is evaluated
// (the raster evaluates it at pixel centres; tests/graph/drawing_raster_test.cpp writes the same
// formulas independently). With h = stroke-width / 2 and, per segment a -> b of nonzero length,
// L = sqrt(dx*dx + dy*dy), u = (dx / L, dy / L) (d = b - a), and for a point p and an origin o,
// v = (p.x - o.x, p.y - o.y), t = u.x*v.x + u.y*v.y, cross = u.x*v.y - u.y*v.x:
//   segment body (o = a)           0 <= t <= L and |cross| <= h
//   square cap (o = the end)       at the end: 0 <= t <= h, at the start: -h <= t <= 0; |cross| <= h
//   round cap, round join (o = the point)   v.x*v.x + v.y*v.y <= h*h
//   miter / bevel join at vertex o between the unit directions u1 (in) and u2 (out), when
//     z = u1.x*u2.y - u1.y*u2.x != 0 (a straight or reversing vertex gets none); s = sign(z),
//     outer normals n1 = (s*u1.y, -s*u1.x), n2 = (s*u2.y, -s*u2.x), t1 = u1.v >= 0, t2 = u2.v <= 0:
//       miter when limit*limit * (1 + (u1.x*u2.x + u1.y*u2.y)) / 2 >= 1 (miter length / width <=
//       limit): n1.v <= h and n2.v <= h (the quad vertex, outer corners, miter tip);
//       else bevel: (n1+n2).v <= h * (1 + (n1.x*n2.x + n1.y*n2.y)) (the triangle vertex, corners)
//       and |v.x| <= h and |v.y| <= h (true of the triangle anyway; at a turn of nearly 180
//       degrees rounding can make the chord's bound 0 while n1+n2 is not, and the box keeps the
//       piece the sliver it is instead of a half-plane)
//   a subpath whose points all coincide, drawn (not a lone M): round cap -> its disc, square cap
//     -> |v.x| <= h and |v.y| <= h, butt -> nothing.
// Which pieces: consecutive equal points are merged (a closed subpath's last points equal to its
// first too); a body per segment; an open subpath gets caps at its ends and joins at its inner
// points; a closed one (two distinct points or more) a join at every point, the first included.
// Every test is a conjunction of half-planes ax*vx + ay*vy <= c (so monotone along a row of
// pixel centres), or a disc test.
#pragma once
#include <vector>

#include "graph/shape_outline.hpp"
#include "graph/shape_style.hpp"

namespace shapevo::graph {

/// ax * (p.x - origin.x) + ay * (p.y - origin.y) <= c, evaluated as written (no fused multiply-add).
struct HalfPlane {
    double ax = 0, ay = 0, c = 0;
};

/// The points meeting all its half-planes. `bounds` is its box (user units), for rows only.
struct ConvexPiece {
    Vec2 origin;
    HalfPlane planes[7];
    int count = 0;
    Vec2 boundsMin, boundsMax;
};

/// The points with dx*dx + dy*dy <= radius*radius (d = p - centre).
struct DiscPiece {
    Vec2 centre;
    double radius = 0;
};

struct StrokePieces {
    std::vector<ConvexPiece> convex;
    std::vector<DiscPiece> discs;
    std::vector<Vec2> vertices;  ///< scratch: one subpath's points with repeats merged
    void clear() {
        convex.clear();
        discs.clear();
    }
};

/// Appends the pieces of the stroke of `outline` (Form::Polylines) with width 2 * halfWidth.
void appendStrokePieces(const ShapeOutline& outline, double halfWidth, LineCap cap, LineJoin join, double miterLimit,
                        StrokePieces& out);

}  // namespace shapevo::graph
