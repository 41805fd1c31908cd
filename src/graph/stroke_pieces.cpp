// appendStrokePieces (stroke_pieces.hpp): bodies, caps and joins of each subpath, as the header's
// formulas say, each piece with the box of its corners.
#include "graph/stroke_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace stroke_pieces_parts {

/// A segment's unit direction and length.
struct Direction {
    double ux = 0, uy = 0, length = 0;
};

Direction directionOf(Vec2 a, Vec2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l = std::sqrt(dx * dx + dy * dy);
    return {dx / l, dy / l, l};
}

struct PieceBuilder {
    StrokePieces& out;
    double h;

    ConvexPiece& begin(Vec2 origin, std::initializer_list<Vec2> corners) {
        ConvexPiece& p = out.convex.emplace_back();
        p.origin = origin;
        p.boundsMin = p.boundsMax = *corners.begin();
        for (Vec2 c : corners) {
            p.boundsMin = {std::min(p.boundsMin.x, c.x), std::min(p.boundsMin.y, c.y)};
            p.boundsMax = {std::max(p.boundsMax.x, c.x), std::max(p.boundsMax.y, c.y)};
        }
        return p;
    }
    static void add(ConvexPiece& p, double ax, double ay, double c) { p.planes[p.count++] = {ax, ay, c}; }

    /// origin + along * u + across * (-uy, ux)
    static Vec2 at(Vec2 o, const Direction& d, double along, double across) {
        return {o.x + along * d.ux - across * d.uy, o.y + along * d.uy + across * d.ux};
    }

    /// from <= t <= to and |cross| <= h, t and cross about `origin` along `d`.
    void band(Vec2 origin, const Direction& d, double from, double to) {
        ConvexPiece& p = begin(origin, {at(origin, d, from, -h), at(origin, d, from, h), at(origin, d, to, -h), at(origin, d, to, h)});
        add(p, -d.ux, -d.uy, -from);
        add(p, d.ux, d.uy, to);
        add(p, -d.uy, d.ux, h);
        add(p, d.uy, -d.ux, h);
    }

    void disc(Vec2 centre) { out.discs.push_back({centre, h}); }

    void cap(LineCap cap, Vec2 end, const Direction& d, bool atStart) {
        if (cap == LineCap::Round) disc(end);
        else if (cap == LineCap::Square) band(end, d, atStart ? -h : 0, atStart ? 0 : h);
    }

    /// A subpath of one point: a dot as its cap draws it.
    void dot(LineCap cap, Vec2 p) {
        if (cap == LineCap::Round) {
            disc(p);
        } else if (cap == LineCap::Square) {
            ConvexPiece& q = begin(p, {{p.x - h, p.y - h}, {p.x + h, p.y + h}});
            add(q, 1, 0, h);
            add(q, -1, 0, h);
            add(q, 0, 1, h);
            add(q, 0, -1, h);
        }
    }

    void join(LineJoin join, double miterLimit, Vec2 o, const Direction& d1, const Direction& d2) {
        if (join == LineJoin::Round) {
            disc(o);
            return;
        }
        const double z = d1.ux * d2.uy - d1.uy * d2.ux;
        if (z == 0) return;  // straight on (the bodies meet) or back (a bevel of no area)
        const double s = z > 0 ? 1 : -1;
        const double n1x = s * d1.uy, n1y = -s * d1.ux, n2x = s * d2.uy, n2y = -s * d2.ux;
        const double nn = n1x * n2x + n1y * n2y;
        const Vec2 c1{o.x + h * n1x, o.y + h * n1y}, c2{o.x + h * n2x, o.y + h * n2y};
        const bool miter = join == LineJoin::Miter && miterLimit * miterLimit * (1 + (d1.ux * d2.ux + d1.uy * d2.uy)) / 2 >= 1;
        if (miter) {
            const double k = h / (1 + nn);
            ConvexPiece& p = begin(o, {o, c1, c2, {o.x + k * (n1x + n2x), o.y + k * (n1y + n2y)}});
            add(p, -d1.ux, -d1.uy, 0);
            add(p, d2.ux, d2.uy, 0);
            add(p, n1x, n1y, h);
            add(p, n2x, n2y, h);
        } else {
            ConvexPiece& p = begin(o, {o, c1, c2, {o.x - h, o.y - h}, {o.x + h, o.y + h}});
            add(p, -d1.ux, -d1.uy, 0);
            add(p, d2.ux, d2.uy, 0);
            add(p, n1x + n2x, n1y + n2y, h * (1 + nn));
            add(p, 1, 0, h);
            add(p, -1, 0, h);
            add(p, 0, 1, h);
            add(p, 0, -1, h);
        }
    }
};

}  // namespace stroke_pieces_parts

void appendStrokePieces(const ShapeOutline& outline, double halfWidth, LineCap cap, LineJoin join, double miterLimit,
                        StrokePieces& out) {
    using namespace stroke_pieces_parts;
    if (!(halfWidth > 0)) return;
    PieceBuilder b{out, halfWidth};
    std::vector<Vec2>& v = out.vertices;
    for (const Subpath& sp : outline.subpaths) {
        v.clear();
        for (std::uint32_t i = sp.begin; i < sp.end; ++i)
            if (v.empty() || !(outline.points[i] == v.back())) v.push_back(outline.points[i]);
        if (sp.closed)
            while (v.size() > 1 && v.back() == v.front()) v.pop_back();
        const std::size_t m = v.size();
        if (m == 0) continue;
        if (m == 1) {
            if (sp.drawn) b.dot(cap, v[0]);
            continue;
        }
        const std::size_t segments = sp.closed ? m : m - 1;
        Direction first{}, previous{};
        for (std::size_t i = 0; i < segments; ++i) {
            const Vec2 a = v[i], e = v[(i + 1) % m];
            const Direction d = directionOf(a, e);
            b.band(a, d, 0, d.length);
            if (i == 0) first = d;
            else b.join(join, miterLimit, a, previous, d);
            previous = d;
        }
        if (sp.closed) {
            b.join(join, miterLimit, v[0], previous, first);
        } else {
            b.cap(cap, v[0], first, true);
            b.cap(cap, v[m - 1], previous, false);
        }
    }
}

}  // namespace shapevo::graph
