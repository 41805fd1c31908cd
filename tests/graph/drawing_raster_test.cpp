// DrawingRaster (graph/drawing_raster.hpp) equals a brute-force test of its coverage rule at every
// pixel centre: 1,000 random drawings per shape kind (lines with each cap, circles filled and
// stroked, rects with each join and miter limit, paths of lines, quads and cubics, open and
// closed, each join, both fill rules, rotated images, the Drawing's defaults and what hides a
// shape), on random frames of 48x48 to 96x96 pixels; plus derived drawings of the shipped tree
// and Koch grammars and a few hand-counted cases. The brute force shares the style and outline
// (the flattened polyline IS the shape) but not the coverage: its own stroke decomposition,
// per-point tests (distance to a segment, caps, joins with the miter limit from the angle) and a
// winding-number point-in-polygon test, evaluated at every pixel centre.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "graph/drawing_raster.hpp"
#include "graph/read_graph_grammar.hpp"
#include "graph/shape_style.hpp"
#include "seeded_derivation.hpp"

namespace shapevo::graph {
namespace drawing_raster_brute {

// ---- the brute force: the coverage rule at one point, for one shape ----------------------------

struct Segment {
    Vec2 a;
    double ux = 0, uy = 0, length = 0;
};
Segment segmentOf(Vec2 a, Vec2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l = std::sqrt(dx * dx + dy * dy);
    return {a, dx / l, dy / l, l};
}
struct Corner {  // a join: the vertex, the direction in and out
    Vec2 o;
    Segment in, out;
};
struct End {  // a cap: the end point, the direction along the segment, at the start or the end
    Vec2 o;
    Segment along;
    bool start = false;
};

struct Box {
    double minY = 0, maxY = 0;
    bool spans(double y) const { return y >= minY && y <= maxY; }
};

struct Prepared {
    bool circle = false, fill = false, stroke = false;
    Vec2 centre;
    double radius = 0, h = 0, limit = 4;
    LineCap cap = LineCap::Butt;
    LineJoin join = LineJoin::Miter;
    FillRule rule = FillRule::NonZero;
    std::vector<std::pair<Vec2, Vec2>> edges;
    std::vector<Segment> segments;
    std::vector<Corner> corners;
    std::vector<End> ends;
    std::vector<Vec2> dots;
    // Only to look at fewer items per row (generous: a far point is covered by none of them).
    std::vector<Box> segmentRows, cornerRows, endRows;
    std::vector<std::uint32_t> rowSegments, rowCorners, rowEnds;  // those spanning the current row
    std::vector<std::pair<Vec2, Vec2>> rowEdges;                   // the edges the current row crosses
    double minX = 0, minY = 0, maxX = 0, maxY = 0;  // only to skip far points (generously)
};

Prepared prepare(const Shape& s, const RasterFrame& f) {
    Prepared p;
    const ShapeStyle st = styleOf(s);
    if (!st.visible()) return p;
    const bool image = s.kind == ShapeKind::Image;
    p.fill = image || st.paintsFill();
    p.stroke = !image && st.paintsStroke();
    p.h = st.strokeWidth / 2;
    p.cap = st.cap;
    p.join = st.join;
    p.limit = st.miterLimit;
    p.rule = image ? FillRule::NonZero : st.fillRule;
    ShapeOutline o;
    PathData scratch;
    outlineOf(s, kFlatteningTolerancePixels / f.pixelsPerUnit, scratch, o);
    if (o.form == ShapeOutline::Form::None) p.fill = p.stroke = false;
    const double grow = p.h * std::max(p.limit, 1.5) + 2 / f.pixelsPerUnit;
    if (o.form == ShapeOutline::Form::Circle) {
        p.circle = true;
        p.centre = o.centre;
        p.radius = o.radius;
        const double e = p.radius + p.h + 2 / f.pixelsPerUnit;
        p.minX = p.centre.x - e, p.maxX = p.centre.x + e, p.minY = p.centre.y - e, p.maxY = p.centre.y + e;
        return p;
    }
    p.minX = p.minY = 1e300;
    p.maxX = p.maxY = -1e300;
    for (Vec2 q : o.points) {
        p.minX = std::min(p.minX, q.x - grow), p.maxX = std::max(p.maxX, q.x + grow);
        p.minY = std::min(p.minY, q.y - grow), p.maxY = std::max(p.maxY, q.y + grow);
    }
    for (const Subpath& sp : o.subpaths) {
        for (std::uint32_t k = sp.begin; k < sp.end; ++k)  // every subpath closed for the fill
            p.edges.emplace_back(o.points[k], o.points[k + 1 < sp.end ? k + 1 : sp.begin]);
        std::vector<Vec2> v;
        for (std::uint32_t k = sp.begin; k < sp.end; ++k)
            if (v.empty() || !(v.back() == o.points[k])) v.push_back(o.points[k]);
        if (sp.closed)
            while (v.size() > 1 && v.back() == v.front()) v.pop_back();
        if (v.size() == 1) {
            if (sp.drawn) p.dots.push_back(v[0]);
            continue;
        }
        const std::size_t n = v.size(), count = sp.closed ? n : n - 1;
        std::vector<Segment> here;
        for (std::size_t k = 0; k < count; ++k) here.push_back(segmentOf(v[k], v[(k + 1) % n]));
        p.segments.insert(p.segments.end(), here.begin(), here.end());
        for (std::size_t k = 1; k < count; ++k) p.corners.push_back({v[k], here[k - 1], here[k]});
        if (sp.closed) {
            p.corners.push_back({v[0], here.back(), here.front()});
        } else {
            p.ends.push_back({v[0], here.front(), true});
            p.ends.push_back({v[n - 1], here.back(), false});
        }
    }
    const auto around = [&](Vec2 a, Vec2 b) { return Box{std::min(a.y, b.y) - grow, std::max(a.y, b.y) + grow}; };
    for (const Segment& g : p.segments) p.segmentRows.push_back(around(g.a, {g.a.x + g.ux * g.length, g.a.y + g.uy * g.length}));
    for (const Corner& c : p.corners) p.cornerRows.push_back(around(c.o, c.o));
    for (const End& e : p.ends) p.endRows.push_back(around(e.o, e.o));
    return p;
}

bool windingInside(const Prepared& p, double x, double y) {
    int winding = 0;
    for (const auto& [a, b] : p.rowEdges) {
        const Vec2 lo = a.y < b.y ? a : b, hi = a.y < b.y ? b : a;
        const double crossing = lo.x + (y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y);
        if (crossing <= x) winding += a.y < b.y ? 1 : -1;
    }
    return p.rule == FillRule::EvenOdd ? winding % 2 != 0 : winding != 0;
}

bool nearSegment(const Segment& s, double x, double y, double from, double to, double h, Vec2 o) {
    const double vx = x - o.x, vy = y - o.y;
    const double t = s.ux * vx + s.uy * vy, cross = s.ux * vy - s.uy * vx;
    return t >= from && t <= to && std::fabs(cross) <= h;
}

bool inDisc(Vec2 c, double r, double x, double y) {
    const double dx = x - c.x, dy = y - c.y;
    return dx * dx + dy * dy <= r * r;
}

bool inCorner(const Prepared& p, const Corner& c, double x, double y) {
    if (p.join == LineJoin::Round) return inDisc(c.o, p.h, x, y);
    const Segment &a = c.in, &b = c.out;
    const double z = a.ux * b.uy - a.uy * b.ux;
    if (z == 0) return false;
    const double s = z > 0 ? 1 : -1;
    const double n1x = s * a.uy, n1y = -s * a.ux, n2x = s * b.uy, n2y = -s * b.ux;
    const double vx = x - c.o.x, vy = y - c.o.y;
    if (!(a.ux * vx + a.uy * vy >= 0 && b.ux * vx + b.uy * vy <= 0)) return false;
    // The miter ratio from the angle between the segments at the vertex.
    const double angle = std::acos(std::clamp(-(a.ux * b.ux + a.uy * b.uy), -1.0, 1.0));
    const bool miter = p.join == LineJoin::Miter && 1 / std::sin(angle / 2) <= p.limit;
    if (miter) return n1x * vx + n1y * vy <= p.h && n2x * vx + n2y * vy <= p.h;
    return (n1x + n2x) * vx + (n1y + n2y) * vy <= p.h * (1 + (n1x * n2x + n1y * n2y)) && std::fabs(vx) <= p.h &&
           std::fabs(vy) <= p.h;
}

bool strokeCovers(const Prepared& p, double x, double y) {
    const double h = p.h;
    for (std::uint32_t k : p.rowSegments)
        if (nearSegment(p.segments[k], x, y, 0, p.segments[k].length, h, p.segments[k].a)) return true;
    for (std::uint32_t k : p.rowEnds) {
        const End& e = p.ends[k];
        if (p.cap == LineCap::Round && inDisc(e.o, h, x, y)) return true;
        if (p.cap == LineCap::Square && nearSegment(e.along, x, y, e.start ? -h : 0, e.start ? 0 : h, h, e.o)) return true;
    }
    for (Vec2 d : p.dots) {
        if (p.cap == LineCap::Round && inDisc(d, h, x, y)) return true;
        if (p.cap == LineCap::Square && std::fabs(x - d.x) <= h && std::fabs(y - d.y) <= h) return true;
    }
    for (std::uint32_t k : p.rowCorners)
        if (inCorner(p, p.corners[k], x, y)) return true;
    return false;
}

bool covers(const Prepared& p, double x, double y) {
    if (!(p.fill || p.stroke) || x < p.minX || x > p.maxX || y < p.minY || y > p.maxY) return false;
    if (p.circle) {
        const double dx = x - p.centre.x, dy = y - p.centre.y, d2 = dx * dx + dy * dy;
        if (p.fill && d2 <= p.radius * p.radius) return true;
        const double outer = p.radius + p.h, inner = p.radius - p.h;
        return p.stroke && d2 <= outer * outer && !(inner > 0 && d2 < inner * inner);
    }
    return (p.fill && windingInside(p, x, y)) || (p.stroke && strokeCovers(p, x, y));
}

// ---- comparing ---------------------------------------------------------------------------------

struct Tally {
    long drawings = 0, pixels = 0, covered = 0, mismatches = 0;
    std::string first;
};

void compare(const Drawing& d, const RasterFrame& f, DrawingRaster& raster, Tally& tally) {
    std::vector<Prepared> shapes;
    for (const Shape& s : d.shapes) shapes.push_back(prepare(s, f));
    const std::int64_t covered = raster.rasterize(d, f);
    std::int64_t counted = 0;
    for (int j = 0; j < f.height; ++j) {
        for (Prepared& p : shapes) {
            const double y = f.centreY(j);
            const auto keep = [y](const std::vector<Box>& rows, std::vector<std::uint32_t>& out) {
                out.clear();
                for (std::uint32_t k = 0; k < rows.size(); ++k)
                    if (rows[k].spans(y)) out.push_back(k);
            };
            keep(p.segmentRows, p.rowSegments);
            keep(p.cornerRows, p.rowCorners);
            keep(p.endRows, p.rowEnds);
            p.rowEdges.clear();
            for (const auto& [a, b] : p.edges)
                if (std::min(a.y, b.y) <= y && y < std::max(a.y, b.y)) p.rowEdges.emplace_back(a, b);
        }
        for (int i = 0; i < f.width; ++i) {
            const double x = f.centreX(i), y = f.centreY(j);
            bool want = false;
            for (const Prepared& p : shapes) want = want || covers(p, x, y);
            const bool got = raster.covered(i, j);
            counted += got;
            if (want != got && tally.mismatches++ == 0) {
                char text[160];
                std::snprintf(text, sizeof text, "drawing %ld pixel (%d, %d) at (%.17g, %.17g): raster %d, brute force %d",
                              tally.drawings, i, j, x, y, int(got), int(want));
                tally.first = text;
                for (const Shape& sh : d.shapes) {
                    tally.first += "\n kind " + std::to_string(int(sh.kind));
                    for (const auto& a : sh.attributes) tally.first += " " + a.name + "=" + a.value;
                }
                char fr[200];
                std::snprintf(fr, sizeof fr, "\n frame %.17g %.17g %.17g %d %d", f.originX, f.originY, f.pixelsPerUnit, f.width, f.height);
                tally.first += fr;
            }
        }
        for (int i = f.width; i < f.wordsPerRow() * 64; ++i)  // bits past the width stay 0
            if ((raster.bits()[std::size_t(j) * std::size_t(f.wordsPerRow()) + std::size_t(i >> 6)] >> (i & 63)) & 1) ++tally.mismatches;
    }
    if (counted != covered || raster.coveredPixels() != covered) ++tally.mismatches;
    tally.covered += counted;
    tally.pixels += std::int64_t(f.width) * f.height;
    ++tally.drawings;
}

// ---- random drawings ---------------------------------------------------------------------------

struct Maker {
    std::mt19937_64 rng;
    RasterFrame frame;

    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    int pick(int n) { return int(rng() % std::uint64_t(n)); }
    static std::string num(double v) {
        char t[40];
        std::snprintf(t, sizeof t, "%.17g", v);
        return t;
    }
    std::string px(double pixels) { return num(pixels / frame.pixelsPerUnit) + "px"; }

    void newFrame() {
        frame.width = 48 + pick(49);
        frame.height = 48 + pick(49);
        frame.pixelsPerUnit = std::exp(uniform(std::log(0.3), std::log(4.0)));
        frame.originX = uniform(-60, 60);
        frame.originY = uniform(-60, 60);
    }
    /// A user point in the frame grown by 20 % on each side.
    Vec2 point() {
        const double w = frame.width / frame.pixelsPerUnit, h = frame.height / frame.pixelsPerUnit;
        return {uniform(frame.originX - 0.2 * w, frame.originX + 1.2 * w), uniform(frame.originY - 0.2 * h, frame.originY + 1.2 * h)};
    }
    static Vec2 model(Vec2 user) { return {user.x / kUserUnitsPerModelUnit, -user.y / kUserUnitsPerModelUnit}; }
    double modelPixels(double pixels) { return pixels / frame.pixelsPerUnit / kUserUnitsPerModelUnit; }

    void strokeStyle(Shape& s, double maxWidthPixels) {
        s.attributes.push_back({"stroke", pick(5) == 0 ? "none" : "black"});
        s.attributes.push_back({"stroke-width", px(uniform(0.2, maxWidthPixels))});
        static const char* caps[] = {"butt", "round", "square"};
        static const char* joins[] = {"miter", "round", "bevel"};
        s.attributes.push_back({"stroke-linecap", caps[pick(3)]});
        s.attributes.push_back({"stroke-linejoin", joins[pick(3)]});
        if (pick(2)) s.attributes.push_back({"stroke-miterlimit", num(uniform(1, 6))});
    }
    void fillStyle(Shape& s) {
        s.attributes.push_back({"fill", pick(3) == 0 ? "none" : "red"});
        if (pick(2)) s.attributes.push_back({"fill-rule", pick(2) ? "evenodd" : "nonzero"});
    }

    Shape line() {
        Shape s;
        s.kind = ShapeKind::Line;
        s.end1 = model(point());
        s.end2 = pick(20) == 0 ? s.end1 : model(point());
        strokeStyle(s, 16);
        return s;
    }
    Shape circle() {
        Shape s;
        s.kind = ShapeKind::Circle;
        s.centre = model(point());
        s.attributes.push_back({"r", px(uniform(0.3, 40))});
        fillStyle(s);
        strokeStyle(s, 24);
        return s;
    }
    Shape rect() {
        Shape s;
        s.kind = ShapeKind::Rect;
        s.centre = model(point());
        s.width = modelPixels(uniform(0.5, 60));
        s.height = modelPixels(uniform(0.5, 60));
        fillStyle(s);
        strokeStyle(s, 16);
        return s;
    }
    Shape image() {
        Shape s;
        s.kind = ShapeKind::Image;
        s.centre = model(point());
        s.width = modelPixels(uniform(0.5, 70));
        s.height = modelPixels(uniform(0.5, 70));
        s.rotation = pick(4) == 0 ? 90.0 * pick(4) : uniform(-360, 360);
        return s;
    }
    Shape path() {
        Shape s;
        s.kind = ShapeKind::Path;
        std::string d;
        const int subpaths = 1 + pick(3);
        for (int k = 0; k < subpaths; ++k) {
            Vec2 p = point();
            d += "M" + num(p.x) + " " + num(p.y);
            const int commands = pick(8) == 0 ? 0 : 1 + pick(5);
            for (int c = 0; c < commands; ++c) {
                const Vec2 a = point(), b = point(), e = pick(12) == 0 ? p : point();
                switch (pick(4)) {
                case 0: d += " L" + num(e.x) + " " + num(e.y); break;
                case 1: d += " Q" + num(a.x) + " " + num(a.y) + " " + num(e.x) + " " + num(e.y); break;
                case 2: d += " C" + num(a.x) + " " + num(a.y) + " " + num(b.x) + " " + num(b.y) + " " + num(e.x) + " " + num(e.y); break;
                default: d += " l" + num((e.x - p.x) / 4) + " " + num((e.y - p.y) / 4); break;
                }
                p = e;
            }
            if (pick(2)) d += " Z";
        }
        s.attributes.push_back({"d", d});
        fillStyle(s);
        strokeStyle(s, 12);
        return s;
    }
    /// The Drawing's defaults (an untagged vertex, an edge) and what hides a shape.
    Shape defaultsOrHidden() {
        Shape s;
        if (pick(2)) {
            s.kind = ShapeKind::Circle;
            s.centre = model(point());
            s.attributes = {{"fill", "none"}, {"r", "0.4cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}};
        } else {
            s.kind = ShapeKind::Line;
            s.end1 = model(point());
            s.end2 = model(point());
            s.attributes = {{"stroke", "black"}, {"stroke-width", "1mm"}};
        }
        static const DrawAttribute hiders[] = {{"opacity", "0"}, {"display", "none"}, {"visibility", "hidden"},
                                               {"stroke-opacity", "0"}, {"fill", "blue"}, {"opacity", "0.5"}};
        if (pick(2)) s.attributes.push_back(hiders[pick(6)]);
        return s;
    }
};

template <class Make>
Tally compareRandom(std::uint64_t seed, Make make) {
    Maker m{std::mt19937_64(seed), {}};
    DrawingRaster raster;
    Tally tally;
    for (int k = 0; k < 1000; ++k) {
        m.newFrame();
        Drawing d;
        const int shapes = 1 + m.pick(3);
        for (int s = 0; s < shapes; ++s) d.shapes.push_back(make(m));
        compare(d, m.frame, raster, tally);
    }
    return tally;
}

/// Exact, and not vacuous: between 2 % and 90 % of the pixels covered over the 1,000 drawings.
void expectExact(const Tally& t) {
    EXPECT_EQ(t.mismatches, 0) << t.first;
    EXPECT_GT(t.covered, t.pixels / 50);
    EXPECT_LT(t.covered, t.pixels * 9 / 10);
}

RasterFrame unitFrame(int w, int h) { return {0, 0, 1, w, h}; }

}  // namespace drawing_raster_brute

using namespace drawing_raster_brute;

TEST(DrawingRaster, LinesWithEachCapEqualBruteForce) { expectExact(compareRandom(1, [](Maker& m) { return m.line(); })); }
TEST(DrawingRaster, CirclesFilledAndStrokedEqualBruteForce) { expectExact(compareRandom(2, [](Maker& m) { return m.circle(); })); }
TEST(DrawingRaster, RectsWithEachJoinAndMiterLimitEqualBruteForce) { expectExact(compareRandom(3, [](Maker& m) { return m.rect(); })); }
TEST(DrawingRaster, PathsOfLinesQuadsCubicsEachJoinAndFillRuleEqualBruteForce) {
    expectExact(compareRandom(4, [](Maker& m) { return m.path(); }));
}
TEST(DrawingRaster, RotatedImagesEqualBruteForce) { expectExact(compareRandom(5, [](Maker& m) { return m.image(); })); }
TEST(DrawingRaster, DrawingDefaultsAndHiddenShapesEqualBruteForce) {
    expectExact(compareRandom(6, [](Maker& m) { return m.defaultsOrHidden(); }));
}

// Boundaries through pixel centres: paths and circles on the half-integer grid of a 1-pixel-per-
// unit frame, with whole-number half widths, so that a centre lies exactly on a stroke's edge, a
// cap, a disc's rim, a fill edge or a vertex's row in nearly every drawing: the inclusive and
// half-open choices of the rule must be made alike.
TEST(DrawingRaster, BoundariesThroughPixelCentresEqualBruteForce) {
    std::mt19937_64 rng(7);
    const auto grid = [&] { return Maker::num(double(rng() % 48) + 8.5); };
    static const char* caps[] = {"butt", "round", "square"};
    static const char* joins[] = {"miter", "round", "bevel"};
    DrawingRaster raster;
    Tally tally;
    for (int k = 0; k < 1000; ++k) {
        Drawing d;
        Shape s;
        s.kind = ShapeKind::Path;
        std::string path = "M" + grid() + " " + grid();
        for (int c = 0, n = 1 + int(rng() % 4); c < n; ++c) path += (rng() % 2 ? " H" : " V") + grid();
        if (rng() % 2) path += " L" + grid() + " " + grid();
        if (rng() % 2) path += " Z";
        s.attributes = {{"d", path}, {"fill", rng() % 2 ? "red" : "none"}, {"fill-rule", rng() % 2 ? "evenodd" : "nonzero"},
                        {"stroke", "black"}, {"stroke-width", std::to_string(2 * (1 + rng() % 3))},
                        {"stroke-linecap", caps[rng() % 3]}, {"stroke-linejoin", joins[rng() % 3]}};
        d.shapes.push_back(s);
        compare(d, {0, 0, 1, 64, 64}, raster, tally);
        // A circle at the user origin (exact) seen with pixel centres on whole numbers: rims of
        // whole-number radii pass through centres (3-4-5 and the axes).
        Shape c;
        c.kind = ShapeKind::Circle;
        c.attributes = {{"r", std::to_string(1 + rng() % 12)}, {"fill", rng() % 2 ? "red" : "none"}, {"stroke", "black"},
                        {"stroke-width", std::to_string(2 * (rng() % 3))}};
        compare(Drawing{{c}}, {-32.5, -32.5, 1, 64, 64}, raster, tally);
    }
    expectExact(tally);
}

TEST(DrawingRaster, DerivedTreeAndKochDrawingsEqualBruteForce) {
    DrawingRaster raster;
    Tally tally;
    for (const char* name : {"tree.yml", "koch.yml"}) {
        const std::string file = test::sourcePath(std::string("grammars/graph/") + name);
        const GraphGrammar g = readGraphGrammar(file);
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const DeriveResult r = test_support::deriveSeeded(g, seed);
            const Drawing d = drawingOf(r.graph, g.names, file);
            compare(d, frameFitting(canvasOf(d, 0.5), 128, 96), raster, tally);
        }
    }
    expectExact(tally);
}

TEST(DrawingRaster, CapsExtendAHorizontalLineAsSvgSays) {
    // A line from x 10 to 30 at y 20, 4 wide: rows 18.5..21.5, columns 10.5..29.5 (butt).
    Shape s;
    s.kind = ShapeKind::Line;
    s.end1 = Maker::model({10, 20});
    s.end2 = Maker::model({30, 20});
    Drawing d;
    DrawingRaster raster;
    const auto count = [&](const char* cap) {
        d.shapes = {s};
        d.shapes[0].attributes = {{"stroke", "black"}, {"stroke-width", "4"}, {"stroke-linecap", cap}};
        return raster.rasterize(d, unitFrame(40, 40));
    };
    EXPECT_EQ(count("butt"), 4 * 20);
    EXPECT_EQ(count("square"), 4 * 24);
    EXPECT_EQ(count("round"), 4 * 20 + 2 * 6);  // a half disc of radius 2 at each end: 6 centres
}

TEST(DrawingRaster, UntaggedVertexIsAnAnnulus) {
    Shape s;
    s.kind = ShapeKind::Circle;
    s.centre = Maker::model({50, 50});
    s.attributes = {{"fill", "none"}, {"r", "0.4cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}};
    Drawing d{{s}};
    DrawingRaster raster;
    raster.rasterize(d, {0, 0, 2, 200, 200});  // pixel i's centre at x = (i + 0.5) / 2
    const double r = 0.4 * 96 / 2.54;
    EXPECT_FALSE(raster.covered(99, 99));                  // the centre: inside the hole
    EXPECT_TRUE(raster.covered(int(2 * (50 + r)), 100));   // on the circle
    EXPECT_FALSE(raster.covered(int(2 * (50 + r + 3)), 100));
}

TEST(DrawingRaster, MiterLimitBevelsARectanglesCorners) {
    // A 20x20 square at (10, 10)-(30, 30), stroke 4: the miter corner reaches (8, 8); a bevel
    // cuts it along x + y = 18 - ... (the corner pixel centre (8.5, 8.5) is then outside).
    Shape s;
    s.kind = ShapeKind::Rect;
    s.centre = Maker::model({20, 20});
    s.width = s.height = 20 / kUserUnitsPerModelUnit;
    Drawing d;
    DrawingRaster raster;
    const auto corner = [&](const char* limit) {
        d.shapes = {s};
        d.shapes[0].attributes = {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "4"}, {"stroke-miterlimit", limit}};
        raster.rasterize(d, unitFrame(40, 40));
        return raster.covered(8, 8);
    };
    EXPECT_TRUE(corner("4"));
    EXPECT_FALSE(corner("1.2"));  // below sqrt(2): every right angle is bevelled
}

TEST(DrawingRaster, EvenOddLeavesTheHoleOfTwoNestedSquares) {
    Shape s;
    s.kind = ShapeKind::Path;
    Drawing d;
    DrawingRaster raster;
    const auto hole = [&](const char* rule) {
        d.shapes = {s};
        d.shapes[0].attributes = {{"d", "M2 2 H38 V38 H2 Z M12 12 H28 V28 H12 Z"}, {"fill-rule", rule}};
        raster.rasterize(d, unitFrame(40, 40));
        return !raster.covered(20, 20) && raster.covered(5, 5);
    };
    EXPECT_FALSE(hole("nonzero"));
    EXPECT_TRUE(hole("evenodd"));
}

}  // namespace shapevo::graph

namespace shapevo::graph {
// The stroke of a circle is closed on both rims: r 5, stroke-width 2 covers distances 4 to 6.
TEST(DrawingRaster, CircleStrokeIncludesBothRims) {
    Shape c;
    c.kind = ShapeKind::Circle;
    c.attributes = {{"r", "5"}, {"fill", "none"}, {"stroke", "black"}, {"stroke-width", "2"}};
    DrawingRaster raster;
    raster.rasterize(Drawing{{c}}, {-32.5, -32.5, 1, 64, 64});  // pixel (32 + a, 32 + b) centred at (a, b)
    EXPECT_TRUE(raster.covered(32 + 4, 32));
    EXPECT_TRUE(raster.covered(32 + 6, 32));
    EXPECT_FALSE(raster.covered(32 + 3, 32));
    EXPECT_FALSE(raster.covered(32 + 7, 32));
    EXPECT_TRUE(raster.covered(32 + 3, 32 + 4));  // 3-4-5: on the circle
}
}  // namespace shapevo::graph
