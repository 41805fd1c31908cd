// DrawingRaster (drawing_raster.hpp): per shape its style and outline; circles and stroke pieces
// row by row, each row's run settled by searching with the point test; fills by a scanline over
// the outline's edges (the crossings of a row sorted by their first pixel, the winding swept).
#include "graph/drawing_raster.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "graph/shape_style.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace drawing_raster_parts {

/// `v` as an index in [lo, hi] (NaN: lo).
int clampIndex(double v, int lo, int hi) {
    if (!(v >= lo)) return lo;
    if (v > hi) return hi;
    return int(v);
}

/// The first index in [lo, hi] where `test` holds, or hi + 1: `test` must be false then true
/// along [lo, hi]. Starts at `guess`, gallops away from it, then bisects; a good guess costs two
/// evaluations.
template <class Test>
int firstTrue(int lo, int hi, int guess, const Test& test) {
    if (lo > hi) return hi + 1;
    guess = std::clamp(guess, lo, hi);
    int bad = lo - 1, good = hi + 1;  // test(bad) false or bad == lo - 1; test(good) true or good == hi + 1
    int step = 1;
    if (test(guess)) {  // gallop down
        good = guess;
        for (int probe = guess - 1; probe >= lo; probe = good - step, step *= 2) {
            if (!test(probe)) {
                bad = probe;
                break;
            }
            good = probe;
        }
    } else {  // gallop up
        bad = guess;
        for (int probe = guess + 1; probe <= hi; probe = bad + step, step *= 2) {
            if (test(probe)) {
                good = probe;
                break;
            }
            bad = probe;
        }
    }
    while (good - bad > 1) {
        const int mid = bad + (good - bad) / 2;
        if (test(mid)) good = mid;
        else bad = mid;
    }
    return good;
}

/// The pixel index whose centre is at user coordinate `x` (fractional, unclamped).
double pixelAt(double x, double origin, double ppu) { return (x - origin) * ppu - 0.5; }

}  // namespace drawing_raster_parts

RasterFrame frameFitting(const DrawingCanvas& c, int width, int height) {
    double scale = 1;
    if (c.width > 0 && c.height > 0) scale = std::min(width / c.width, height / c.height);
    else if (c.width > 0) scale = width / c.width;
    else if (c.height > 0) scale = height / c.height;
    RasterFrame f;
    f.pixelsPerUnit = scale;
    f.width = width;
    f.height = height;
    f.originX = c.x - (width - c.width * scale) / 2 / scale;
    f.originY = c.y - (height - c.height * scale) / 2 / scale;
    return f;
}

std::int64_t DrawingRaster::rasterize(const Drawing& drawing, const RasterFrame& frame) {
    frame_ = frame;
    frame_.width = std::max(frame.width, 0);
    frame_.height = std::max(frame.height, 0);
    bits_.assign(std::size_t(frame_.wordsPerRow()) * std::size_t(frame_.height), 0);
    covered_ = 0;
    if (frame_.width > 0 && frame_.height > 0 && frame_.pixelsPerUnit > 0 && std::isfinite(frame_.pixelsPerUnit))
        for (const Shape& s : drawing.shapes) paintShape(s);
    for (std::uint64_t w : bits_) covered_ += std::popcount(w);
    return covered_;
}

void DrawingRaster::paintShape(const Shape& s) {
    const ShapeStyle style = styleOf(s);
    if (!style.visible()) return;
    const bool image = s.kind == ShapeKind::Image;
    const bool fill = image || style.paintsFill(), stroke = !image && style.paintsStroke();
    if (!fill && !stroke) return;
    outlineOf(s, kFlatteningTolerancePixels / frame_.pixelsPerUnit, path_, outline_);
    const double h = style.strokeWidth / 2;
    if (outline_.form == ShapeOutline::Form::Circle) {
        const double r = outline_.radius;
        if (fill) paintDisc(outline_.centre, r, -1);
        if (stroke) paintDisc(outline_.centre, r + h, r - h > 0 ? r - h : -1);
    } else if (outline_.form == ShapeOutline::Form::Polylines) {
        if (fill) fillPolylines(image ? FillRule::NonZero : style.fillRule);
        if (stroke) {
            pieces_.clear();
            appendStrokePieces(outline_, h, style.cap, style.join, style.miterLimit, pieces_);
            for (const ConvexPiece& p : pieces_.convex) paintConvex(p);
            for (const DiscPiece& d : pieces_.discs) paintDisc(d.centre, d.radius, -1);
        }
    }
}

void DrawingRaster::setRun(int j, int from, int to) {
    from = std::max(from, 0);
    to = std::min(to, frame_.width - 1);
    if (from > to) return;
    std::uint64_t* row = bits_.data() + std::size_t(j) * std::size_t(frame_.wordsPerRow());
    const int w0 = from >> 6, w1 = to >> 6;
    const std::uint64_t first = ~std::uint64_t(0) << (from & 63), last = ~std::uint64_t(0) >> (63 - (to & 63));
    if (w0 == w1) {
        row[w0] |= first & last;
        return;
    }
    row[w0] |= first;
    for (int w = w0 + 1; w < w1; ++w) row[w] = ~std::uint64_t(0);
    row[w1] |= last;
}

void DrawingRaster::paintConvex(const ConvexPiece& p) {
    using namespace drawing_raster_parts;
    const RasterFrame& f = frame_;
    const double ppu = f.pixelsPerUnit;
    const int jFrom = clampIndex(std::floor(pixelAt(p.boundsMin.y, f.originY, ppu)) - 1, 0, f.height - 1);
    const int jTo = clampIndex(std::ceil(pixelAt(p.boundsMax.y, f.originY, ppu)) + 1, -1, f.height - 1);
    const int last = f.width - 1;
    for (int j = jFrom; j <= jTo; ++j) {
        const double vy = f.centreY(j) - p.origin.y;
        int lo = 0, hi = last;
        for (int k = 0; k < p.count && lo <= hi; ++k) {
            const HalfPlane& h = p.planes[k];
            const auto inside = [&](int i) { return h.ax * (f.centreX(i) - p.origin.x) + h.ay * vy <= h.c; };
            const double edge = pixelAt(p.origin.x + (h.c - h.ay * vy) / h.ax, f.originX, ppu);
            if (h.ax > 0) {  // inside up to a point
                const int guess = clampIndex(std::floor(edge) + 1, lo, hi + 1);
                hi = firstTrue(lo, hi, guess, [&](int i) { return !inside(i); }) - 1;
            } else if (h.ax < 0) {  // inside from a point on
                lo = firstTrue(lo, hi, clampIndex(std::ceil(edge), lo, hi + 1), inside);
            } else if (!inside(lo)) {  // the same all along the row (NaN: never)
                hi = lo - 1;
            }
        }
        setRun(j, lo, hi);
    }
}

void DrawingRaster::paintDisc(Vec2 c, double radius, double innerRadius) {
    using namespace drawing_raster_parts;
    const RasterFrame& f = frame_;
    const double ppu = f.pixelsPerUnit;
    const int jFrom = clampIndex(std::floor(pixelAt(c.y - radius, f.originY, ppu)) - 1, 0, f.height - 1);
    const int jTo = clampIndex(std::ceil(pixelAt(c.y + radius, f.originY, ppu)) + 1, -1, f.height - 1);
    const int last = f.width - 1;
    const double r2 = radius * radius, ri2 = innerRadius * innerRadius;
    const int middle0 = clampIndex(std::ceil(pixelAt(c.x, f.originX, ppu)), 0, f.width);
    // Left of `middle` the centres' dx <= 0 grow towards 0, right of it they grow from 0 on.
    const int middle = firstTrue(0, last, middle0, [&](int i) { return f.centreX(i) >= c.x; });
    for (int j = jFrom; j <= jTo; ++j) {
        const double dy = f.centreY(j) - c.y;
        const double dy2 = dy * dy;
        // The run where d2 <= bound (strict: < bound), found on both sides of `middle`.
        const auto run = [&](double bound, bool strict, int& lo, int& hi) {
            const auto inside = [&](int i) {
                const double dx = f.centreX(i) - c.x;
                const double d2 = dx * dx + dy2;
                return strict ? d2 < bound : d2 <= bound;
            };
            const double half = std::sqrt(std::max(bound - dy2, 0.0));
            const int left = clampIndex(std::ceil(pixelAt(c.x - half, f.originX, ppu)), 0, middle);
            const int right = clampIndex(std::floor(pixelAt(c.x + half, f.originX, ppu)) + 1, middle, f.width);
            lo = firstTrue(0, middle - 1, left, inside);
            hi = firstTrue(middle, last, right, [&](int i) { return !inside(i); }) - 1;
        };
        int lo = 0, hi = -1;
        run(r2, false, lo, hi);
        if (lo > hi) continue;
        if (innerRadius > 0) {
            int innerLo = 0, innerHi = -1;
            run(ri2, true, innerLo, innerHi);
            if (innerLo <= innerHi) {
                setRun(j, lo, std::min(hi, innerLo - 1));
                setRun(j, std::max(lo, innerHi + 1), hi);
                continue;
            }
        }
        setRun(j, lo, hi);
    }
}

void DrawingRaster::fillPolylines(FillRule rule) {
    using namespace drawing_raster_parts;
    const RasterFrame& f = frame_;
    const double ppu = f.pixelsPerUnit;
    const int lastRow = f.height - 1;
    edges_.clear();
    const auto rowOf = [&](double y) {
        const int guess = clampIndex(std::ceil(pixelAt(y, f.originY, ppu)), 0, f.height);
        return firstTrue(0, lastRow, guess, [&](int j) { return f.centreY(j) >= y; });
    };
    for (const Subpath& sp : outline_.subpaths) {
        for (std::uint32_t k = sp.begin; k < sp.end; ++k) {
            const Vec2 a = outline_.points[k], b = outline_.points[k + 1 < sp.end ? k + 1 : sp.begin];
            if (a.y == b.y) continue;  // on no row (min <= y < max is empty)
            Edge e;
            e.direction = a.y < b.y ? 1 : -1;
            e.lo = a.y < b.y ? a : b;
            e.hi = a.y < b.y ? b : a;
            e.rowBegin = rowOf(e.lo.y);
            e.rowEnd = rowOf(e.hi.y);
            if (e.rowBegin < e.rowEnd) edges_.push_back(e);
        }
    }
    if (edges_.empty()) return;
    std::sort(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) { return x.rowBegin < y.rowBegin; });
    active_.clear();
    std::size_t next = 0;
    for (int j = edges_.front().rowBegin; j <= lastRow; ++j) {
        while (next < edges_.size() && edges_[next].rowBegin <= j) active_.push_back(std::uint32_t(next++));
        std::erase_if(active_, [&](std::uint32_t e) { return edges_[e].rowEnd <= j; });
        if (active_.empty()) {
            if (next == edges_.size()) break;
            continue;
        }
        fillRow(j, rule);
    }
}

void DrawingRaster::fillRow(int j, FillRule rule) {
    using namespace drawing_raster_parts;
    const RasterFrame& f = frame_;
    const double y = f.centreY(j);
    const int last = f.width - 1;
    crossings_.clear();
    for (std::uint32_t k : active_) {
        const Edge& e = edges_[k];
        const double x = e.lo.x + (y - e.lo.y) * (e.hi.x - e.lo.x) / (e.hi.y - e.lo.y);
        const int guess = clampIndex(std::ceil(pixelAt(x, f.originX, f.pixelsPerUnit)), 0, f.width);
        crossings_.push_back({firstTrue(0, last, guess, [&](int i) { return f.centreX(i) >= x; }), e.direction});
    }
    std::sort(crossings_.begin(), crossings_.end(), [](const Crossing& a, const Crossing& b) { return a.pixel < b.pixel; });
    const auto inside = [rule](int winding) { return rule == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0; };
    int winding = 0, from = 0;
    for (const Crossing& c : crossings_) {
        if (c.pixel > from) {
            if (inside(winding)) setRun(j, from, c.pixel - 1);
            from = c.pixel;
        }
        winding += c.direction;
    }
    if (from <= last && inside(winding)) setRun(j, from, last);
}

}  // namespace shapevo::graph
