// outlineOf (shape_outline.hpp): each shape kind's geometry in user units; Bézier flattening by
// the bound on a curve's second derivative (a piece of parameter length h leaves its chord by at
// most h^2 / 8 * max|B''|).
#include "graph/shape_outline.hpp"

#include <algorithm>
#include <cmath>

#include "graph/shape_style.hpp"
#include "graph/svg_paint.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace shape_outline_parts {

constexpr double kPi = 3.14159265358979323846;

/// Pieces so that (h^2 / 8) * bound <= tolerance with h = 1 / pieces, within [1, kMaxCurvePieces].
int piecesFor(double secondDerivativeBound, double tolerance) {
    const double n = std::ceil(std::sqrt(secondDerivativeBound / (8 * tolerance)));
    if (!(n >= 1)) return 1;  // NaN too
    return n > kMaxCurvePieces ? kMaxCurvePieces : int(n);
}

double length(double x, double y) { return std::sqrt(x * x + y * y); }

void rectangle(const Shape& s, ShapeOutline& out) {
    constexpr double k = kUserUnitsPerModelUnit;
    const double x = (s.centre.x - s.width / 2) * k, y = -((s.centre.y + s.height / 2) * k);
    const double w = s.width * k, h = s.height * k;
    Vec2 corners[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
    if (s.kind == ShapeKind::Image && s.rotation != 0) {  // rotate(rotation, cx, cy)
        const double a = s.rotation * kPi / 180, c = std::cos(a), sn = std::sin(a);
        const Vec2 o = userPoint(s.centre);
        for (Vec2& p : corners) {
            const double dx = p.x - o.x, dy = p.y - o.y;
            p = {o.x + (dx * c - dy * sn), o.y + (dx * sn + dy * c)};
        }
    }
    out.points.assign(std::begin(corners), std::end(corners));
    out.subpaths.push_back({0, 4, true, true});
}

void pathOutline(const PathData& path, double tolerance, ShapeOutline& out) {
    Vec2 current, start;
    bool open = false;  // a subpath is being added to (false after Z: the next command starts one)
    auto beginSubpath = [&](Vec2 at) {
        out.subpaths.push_back({std::uint32_t(out.points.size()), std::uint32_t(out.points.size()), false, false});
        out.points.push_back(at);
        start = current = at;
        open = true;
    };
    for (const PathSegment& seg : path.segments) {
        if (seg.op == PathSegment::Op::Move) {
            beginSubpath(seg.p[0]);
        } else {
            if (!open) beginSubpath(start);
            Subpath& sp = out.subpaths.back();
            sp.drawn = true;
            switch (seg.op) {
            case PathSegment::Op::Line: out.points.push_back(seg.p[0]); current = seg.p[0]; break;
            case PathSegment::Op::Quad:
                flattenQuad(current, seg.p[0], seg.p[1], tolerance, out.points);
                current = seg.p[1];
                break;
            case PathSegment::Op::Cubic:
                flattenCubic(current, seg.p[0], seg.p[1], seg.p[2], tolerance, out.points);
                current = seg.p[2];
                break;
            case PathSegment::Op::Close:
                sp.closed = true;
                current = start;
                open = false;
                break;
            case PathSegment::Op::Move: break;
            }
        }
        out.subpaths.back().end = std::uint32_t(out.points.size());
    }
}

}  // namespace shape_outline_parts

Vec2 userPoint(Vec2 p) { return {p.x * kUserUnitsPerModelUnit, -(p.y * kUserUnitsPerModelUnit)}; }

void flattenQuad(Vec2 p0, Vec2 c, Vec2 e, double tolerance, std::vector<Vec2>& points) {
    using namespace shape_outline_parts;
    // B'' = 2 (p0 - 2c + e)
    const int n = piecesFor(2 * length(p0.x - 2 * c.x + e.x, p0.y - 2 * c.y + e.y), tolerance);
    for (int i = 1; i < n; ++i) {
        const double t = double(i) / n, u = 1 - t;
        points.push_back({u * u * p0.x + 2 * u * t * c.x + t * t * e.x, u * u * p0.y + 2 * u * t * c.y + t * t * e.y});
    }
    points.push_back(e);
}

void flattenCubic(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 e, double tolerance, std::vector<Vec2>& points) {
    using namespace shape_outline_parts;
    // |B''| <= 6 max(|p0 - 2c1 + c2|, |c1 - 2c2 + e|)
    const double m = std::max(length(p0.x - 2 * c1.x + c2.x, p0.y - 2 * c1.y + c2.y), length(c1.x - 2 * c2.x + e.x, c1.y - 2 * c2.y + e.y));
    const int n = piecesFor(6 * m, tolerance);
    for (int i = 1; i < n; ++i) {
        const double t = double(i) / n, u = 1 - t;
        const double a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
        points.push_back({a * p0.x + b * c1.x + c * c2.x + d * e.x, a * p0.y + b * c1.y + c * c2.y + d * e.y});
    }
    points.push_back(e);
}

void outlineOf(const Shape& s, double tolerance, PathData& pathScratch, ShapeOutline& out) {
    using namespace shape_outline_parts;
    out.form = ShapeOutline::Form::None;
    out.points.clear();
    out.subpaths.clear();
    switch (s.kind) {
    case ShapeKind::Circle: {
        const std::string* r = attributeOf(s, "r");
        const std::optional<double> radius = r ? parseLength(*r) : std::nullopt;
        if (!radius || !(*radius > 0)) return;  // SVG: r <= 0 is not rendered
        out.form = ShapeOutline::Form::Circle;
        out.centre = userPoint(s.centre);
        out.radius = *radius;
        return;
    }
    case ShapeKind::Line:
        out.form = ShapeOutline::Form::Polylines;
        out.points.push_back(userPoint(s.end1));
        out.points.push_back(userPoint(s.end2));
        out.subpaths.push_back({0, 2, false, true});
        return;
    case ShapeKind::Rect:
    case ShapeKind::Image:
        if (!(s.width > 0) || !(s.height > 0)) return;
        out.form = ShapeOutline::Form::Polylines;
        rectangle(s, out);
        return;
    case ShapeKind::Path: {
        const std::string* d = attributeOf(s, "d");
        if (!d) return;
        parsePathData(*d, pathScratch);
        out.form = ShapeOutline::Form::Polylines;
        pathOutline(pathScratch, tolerance, out);
        return;
    }
    }
}

}  // namespace shapevo::graph
