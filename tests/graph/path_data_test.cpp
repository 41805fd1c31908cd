// Tests of graph/path_data and graph/elliptical_arc: SVG arcs (A/a) parsed into cubic Béziers of at
// most 90 degrees whose ends lie on the ellipse (1e-9) and whose middles stay within 3e-4 of the
// radius; each of the four flag combinations picks the arc an independent construction (the two
// candidate centres tried by brute force) expects; a zero radius is a line, radii too small are
// scaled up, a rotated ellipse keeps its rotation; compact flags, relative arcs, implicit repeats
// and bad flags read as SVG reads them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "graph/path_data.hpp"

namespace path_data_arc_test {

using namespace shapevo::graph;

constexpr double kPi = 3.14159265358979323846;

Vec2 bezier(Vec2 a, const PathSegment& s, double t) {
    const double u = 1 - t;
    const double w0 = u * u * u, w1 = 3 * u * u * t, w2 = 3 * u * t * t, w3 = t * t * t;
    return {w0 * a.x + w1 * s.p[0].x + w2 * s.p[1].x + w3 * s.p[2].x, w0 * a.y + w1 * s.p[0].y + w2 * s.p[1].y + w3 * s.p[2].y};
}

/// An ellipse given by the test, independently of the code under test.
struct Ellipse {
    Vec2 centre;
    double rx = 1, ry = 1, phiDegrees = 0;

    /// The point at parameter angle theta (the forward map; the code computes the inverse).
    Vec2 at(double theta) const {
        const double phi = phiDegrees * kPi / 180;
        const double x = rx * std::cos(theta), y = ry * std::sin(theta);
        return {centre.x + std::cos(phi) * x - std::sin(phi) * y, centre.y + std::sin(phi) * x + std::cos(phi) * y};
    }
    /// The parameter angle of p and its "radius" in ellipse units (1 on the ellipse).
    double angle(Vec2 p) const {
        const Vec2 q = local(p);
        return std::atan2(q.y / ry, q.x / rx);
    }
    double radius(Vec2 p) const {
        const Vec2 q = local(p);
        return std::hypot(q.x / rx, q.y / ry);
    }
    Vec2 local(Vec2 p) const {
        const double phi = phiDegrees * kPi / 180, dx = p.x - centre.x, dy = p.y - centre.y;
        return {std::cos(phi) * dx + std::sin(phi) * dy, -std::sin(phi) * dx + std::cos(phi) * dy};
    }
};

double wrap(double a) {  // into (-pi, pi]
    while (a <= -kPi) a += 2 * kPi;
    while (a > kPi) a -= 2 * kPi;
    return a;
}

/// Checks that `segments` (after a Move to `from`) are cubics tracing `e` from `from` through the
/// signed parameter angle `sweep`, each piece at most 90 degrees; returns the number of pieces.
int expectArc(const std::vector<PathSegment>& segments, Vec2 from, const Ellipse& e, double sweep) {
    Vec2 start = from;
    double swept = 0;
    int pieces = 0;
    const double tolerance = 3e-4;  // in ellipse units: a 90-degree cubic leaves the circle by 2.7e-4 of r
    for (std::size_t i = 1; i < segments.size(); ++i, ++pieces) {
        const PathSegment& s = segments[i];
        EXPECT_EQ(s.op, PathSegment::Op::Cubic) << "piece " << i;
        EXPECT_NEAR(e.radius(bezier(start, s, 0)), 1, 1e-9) << "piece " << i << " starts on the ellipse";
        EXPECT_NEAR(e.radius(bezier(start, s, 1)), 1, 1e-9) << "piece " << i << " ends on the ellipse";
        EXPECT_NEAR(e.radius(bezier(start, s, 0.5)), 1, tolerance) << "piece " << i << "'s middle";
        EXPECT_NEAR(e.radius(bezier(start, s, 0.25)), 1, tolerance) << "piece " << i << "'s quarter";
        const double a0 = e.angle(start), piece = wrap(e.angle(s.p[2]) - a0);
        EXPECT_LE(std::abs(piece), kPi / 2 + 1e-9) << "piece " << i;
        // The middle is halfway round (so the piece goes the short way its ends suggest).
        EXPECT_NEAR(wrap(e.angle(bezier(start, s, 0.5)) - a0), piece / 2, 1e-3) << "piece " << i;
        swept += piece;
        start = s.p[2];
    }
    EXPECT_NEAR(swept, sweep, 1e-9);
    return pieces;
}

std::string num(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

TEST(PathDataArc, FourFlagCombinationsPickTheArcsOfABruteForceConstruction) {
    // Between (1, 0) and (0, 1), either way, radius 1: the candidate centres are (0, 0) and (1, 1).
    const Vec2 centres[2] = {{0, 0}, {1, 1}};
    for (int combination = 0; combination < 8; ++combination) {
        const bool reversed = combination & 4;
        const int large = (combination >> 1) & 1, sweep = combination & 1;
        const Vec2 from = reversed ? Vec2{0, 1} : Vec2{1, 0}, to = reversed ? Vec2{1, 0} : Vec2{0, 1};
        // Independently: for each centre, the angle from `from` to `to` turning the sweep's way
        // (sweep 1: growing angles); the arc is the one whose size agrees with the large flag.
        Ellipse chosen;
        double expected = 0;
        int matches = 0;
        for (const Vec2 c : centres) {
            const Ellipse e{c, 1, 1, 0};
            double turn = e.angle(to) - e.angle(from);
            if (sweep && turn < 0) turn += 2 * kPi;
            if (!sweep && turn > 0) turn -= 2 * kPi;
            if ((std::abs(turn) > kPi) == bool(large)) {
                chosen = e;
                expected = turn;
                ++matches;
            }
        }
        ASSERT_EQ(matches, 1);
        const std::string d = "M" + num(from.x) + " " + num(from.y) + " A1 1 0 " + std::to_string(large) + " " +
                              std::to_string(sweep) + " " + num(to.x) + " " + num(to.y);
        SCOPED_TRACE(d);
        const PathData p = parsePathData(d);
        EXPECT_TRUE(p.complete);
        const int pieces = expectArc(p.segments, from, chosen, expected);
        EXPECT_EQ(pieces, large ? 3 : 1);
        EXPECT_EQ(p.segments.back().p[2], to) << "the arc ends exactly at its end point";
    }
}

TEST(PathDataArc, RotatedEllipseArcStaysOnItsEllipse) {
    const Ellipse e{{10, -4}, 6, 2.5, 30};
    const double t1 = 0.4, t2 = 0.4 + 1.75 * kPi;  // 315 degrees of the parameter, through growing angles
    const Vec2 from = e.at(t1), to = e.at(t2);
    const std::string d = "M" + num(from.x) + " " + num(from.y) + "A6 2.5 30 1 1 " + num(to.x) + " " + num(to.y);
    const PathData p = parsePathData(d);
    EXPECT_TRUE(p.complete);
    EXPECT_EQ(expectArc(p.segments, from, e, 1.75 * kPi), 4);
    // The other way round the same ellipse: the small arc, turning back (sweep 0).
    const std::string back = "M" + num(from.x) + " " + num(from.y) + "A6 2.5 390 0 0 " + num(to.x) + " " + num(to.y);
    EXPECT_EQ(expectArc(parsePathData(back).segments, from, e, -0.25 * kPi), 1);
}

TEST(PathDataArc, ZeroRadiusIsALineAndEqualEndsDrawNothing) {
    for (const char* d : {"M0 0 A0 5 0 0 1 3 4", "M0 0 A5 0 0 0 1 3 4", "M0 0 a0 0 0 1 1 3 4"}) {
        const PathData p = parsePathData(d);
        ASSERT_EQ(p.segments.size(), 2u) << d;
        EXPECT_EQ(p.segments[1].op, PathSegment::Op::Line) << d;
        EXPECT_EQ(p.segments[1].p[0], (Vec2{3, 4})) << d;
    }
    const PathData same = parsePathData("M2 2 A1 1 0 0 1 2 2 L5 5");
    EXPECT_TRUE(same.complete);
    ASSERT_EQ(same.segments.size(), 2u);
    EXPECT_EQ(same.segments[1].op, PathSegment::Op::Line);
}

TEST(PathDataArc, RadiiTooSmallAreScaledUpKeepingTheirRatio) {
    // Chord 4 along x; rx 1 and ry 0.5 scale by 2 to 2 and 1: a half ellipse about (2, 0).
    const PathData p = parsePathData("M0 0 A1 0.5 0 0 1 4 0");
    EXPECT_TRUE(p.complete);
    EXPECT_EQ(expectArc(p.segments, {0, 0}, Ellipse{{2, 0}, 2, 1, 0}, kPi), 2);
    // The sweep decides the side: sweep 1 goes through growing angles, here through y = -1
    // (angle -pi to 0, by the top on the y-down screen); sweep 0 through y = +1.
    EXPECT_NEAR(p.segments[1].p[2].y, -1, 1e-12);
    EXPECT_NEAR(parsePathData("M0 0 A1 0.5 0 1 0 4 0").segments[1].p[2].y, 1, 1e-12);
    // Negative radii count by their size.
    const PathData negative = parsePathData("M0 0 A-1 -0.5 0 0 1 4 0");
    ASSERT_EQ(negative.segments.size(), p.segments.size());
    EXPECT_EQ(negative.segments[1].p[2], p.segments[1].p[2]);
}

TEST(PathDataArc, CompactFlagsRelativeArcsAndRepeatsReadAsSvg) {
    const PathData spaced = parsePathData("M10 10 A1 1 0 0 0 11 11");
    for (const char* d : {"M10 10a1 1 0 00 1 1", "M10,10a1,1,0,0,0,1,1", "M10 10a1 1 0 001 1"}) {
        const PathData p = parsePathData(d);
        EXPECT_TRUE(p.complete) << d;
        ASSERT_EQ(p.segments.size(), spaced.segments.size()) << d;
        for (std::size_t i = 0; i < p.segments.size(); ++i)
            for (int k = 0; k < 3; ++k) EXPECT_EQ(p.segments[i].p[k], spaced.segments[i].p[k]) << d;
    }
    // "a1 1 0 1110 10": the flags 1 and 1, then the numbers 10 and 10.
    const PathData packed = parsePathData("M0 0a10 10 0 1110 10");
    EXPECT_TRUE(packed.complete);
    EXPECT_EQ(packed.segments.back().p[2], (Vec2{10, 10}));
    EXPECT_EQ(packed.segments.size(), 4u) << "the large arc: 270 degrees in three pieces";
    // Relative arcs from the current point, repeated without a letter, and a relative line after.
    const PathData rel = parsePathData("M10 10 a5 5 0 0 1 10 0 5 5 0 0 1 -10 0 l0 3");
    EXPECT_TRUE(rel.complete);
    ASSERT_EQ(rel.segments.size(), 6u);
    expectArc(std::vector<PathSegment>(rel.segments.begin(), rel.segments.begin() + 3), {10, 10}, Ellipse{{15, 10}, 5, 5, 0}, kPi);
    EXPECT_NEAR(rel.segments[3].p[2].x, 15, 1e-12) << "back through the bottom (y down: y grows)";
    EXPECT_NEAR(rel.segments[3].p[2].y, 15, 1e-12);
    EXPECT_EQ(rel.segments[4].p[2], (Vec2{10, 10}));
    EXPECT_EQ(rel.segments[5].op, PathSegment::Op::Line);
    EXPECT_EQ(rel.segments[5].p[0], (Vec2{10, 13}));
}

TEST(PathDataArc, BadFlagsOrMissingNumbersCutThePathThere) {
    for (const char* d : {"M0 0 L1 1 A1 1 0 2 0 3 3", "M0 0 L1 1 A1 1 0 0 1 3", "M0 0 L1 1 A1 1 0 0 .5 3 3", "M0 0 L1 1 A1 1"}) {
        const PathData p = parsePathData(d);
        EXPECT_FALSE(p.complete) << d;
        EXPECT_EQ(p.segments.size(), 2u) << d;
    }
    EXPECT_FALSE(parsePathData("A1 1 0 0 1 3 3").complete) << "a path starts with M";
    EXPECT_TRUE(parsePathData("M0 0 A1 1 0 0 1 1 1 Z").complete);
}

}  // namespace path_data_arc_test
