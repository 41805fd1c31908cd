// appendArcSegments (elliptical_arc.hpp): SVG 1.1 appendix F.6.5's endpoint-to-centre conversion,
// then the sweep cut into equal pieces of at most 90 degrees, each the usual cubic whose handles are
// 4/3 tan(piece / 4) of the ellipse's tangent at its ends.
#include "graph/elliptical_arc.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace elliptical_arc_parts {

constexpr double kPi = 3.14159265358979323846;

struct Ellipse {
    Vec2 centre;
    double rx = 0, ry = 0, cosPhi = 1, sinPhi = 0;

    Vec2 at(double theta) const {
        const double c = std::cos(theta), s = std::sin(theta);
        return {centre.x + rx * cosPhi * c - ry * sinPhi * s, centre.y + rx * sinPhi * c + ry * cosPhi * s};
    }
    /// d at(theta) / d theta.
    Vec2 tangent(double theta) const {
        const double c = std::cos(theta), s = std::sin(theta);
        return {-rx * cosPhi * s - ry * sinPhi * c, -rx * sinPhi * s + ry * cosPhi * c};
    }
};

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

PathSegment lineTo(Vec2 to) {
    PathSegment seg;
    seg.op = PathSegment::Op::Line;
    seg.p[0] = to;
    return seg;
}

}  // namespace elliptical_arc_parts

void appendArcSegments(const EllipticalArc& arc, std::vector<PathSegment>& out) {
    using namespace elliptical_arc_parts;
    if (arc.from == arc.to) return;  // F.6.2: the arc is omitted
    Ellipse e;
    e.rx = std::abs(arc.rx);
    e.ry = std::abs(arc.ry);
    if (!(e.rx > 0) || !(e.ry > 0)) {  // F.6.2: a straight line
        out.push_back(lineTo(arc.to));
        return;
    }
    const double phi = std::fmod(arc.xAxisRotationDegrees, 360.0) * kPi / 180;
    e.cosPhi = std::cos(phi);
    e.sinPhi = std::sin(phi);
    // F.6.5 step 1: the half chord in the ellipse's axes (x1', y1').
    const double hx = (arc.from.x - arc.to.x) / 2, hy = (arc.from.y - arc.to.y) / 2;
    const double x1 = e.cosPhi * hx + e.sinPhi * hy, y1 = -e.sinPhi * hx + e.cosPhi * hy;
    // F.6.6: radii too small are scaled up by sqrt(lambda); then the centre is on the chord.
    const double lambda = (x1 / e.rx) * (x1 / e.rx) + (y1 / e.ry) * (y1 / e.ry);
    if (lambda > 1) {
        e.rx *= std::sqrt(lambda);
        e.ry *= std::sqrt(lambda);
    }
    // F.6.5 step 2: the centre (cx', cy'); the radicand (rx²ry² - rx²y1'² - ry²x1'²) / (rx²y1'² +
    // ry²x1'²) is 1/lambda - 1 with the radii as given, 0 once they are scaled.
    const double root = (arc.largeArc == arc.sweep ? -1 : 1) * std::sqrt(std::max(0.0, 1 / lambda - 1));
    const double cx1 = root * e.rx * y1 / e.ry, cy1 = -root * e.ry * x1 / e.rx;
    // Step 3: the centre in user units; step 4: the start angle and the signed sweep.
    e.centre = {e.cosPhi * cx1 - e.sinPhi * cy1 + (arc.from.x + arc.to.x) / 2,
                e.sinPhi * cx1 + e.cosPhi * cy1 + (arc.from.y + arc.to.y) / 2};
    const double theta1 = std::atan2((y1 - cy1) / e.ry, (x1 - cx1) / e.rx);
    const double theta2 = std::atan2((-y1 - cy1) / e.ry, (-x1 - cx1) / e.rx);
    double delta = theta2 - theta1;
    if (arc.sweep && delta < 0) delta += 2 * kPi;
    if (!arc.sweep && delta > 0) delta -= 2 * kPi;
    if (!finite(e.centre) || !std::isfinite(delta) || !std::isfinite(e.rx) || !std::isfinite(e.ry)) {
        out.push_back(lineTo(arc.to));  // radii beyond double's range against the chord: no curve to draw
        return;
    }
    // At most 90 degrees a piece (a hair of tolerance keeps an exact quarter in one piece).
    const int pieces = std::clamp(int(std::ceil(std::abs(delta) / (kPi / 2) - 1e-9)), 1, 4);
    const double step = delta / pieces, handle = 4.0 / 3.0 * std::tan(step / 4);
    for (int i = 0; i < pieces; ++i) {
        const double a = theta1 + i * step, b = i + 1 == pieces ? theta1 + delta : a + step;
        const Vec2 start = e.at(a), ta = e.tangent(a), tb = e.tangent(b);
        const Vec2 end = i + 1 == pieces ? arc.to : e.at(b);
        PathSegment seg;
        seg.op = PathSegment::Op::Cubic;
        seg.p[0] = {start.x + handle * ta.x, start.y + handle * ta.y};
        seg.p[1] = {end.x - handle * tb.x, end.y - handle * tb.y};
        seg.p[2] = end;
        out.push_back(seg);
    }
}

}  // namespace shapevo::graph
