// DrawingRaster: an exact bitmap of a Drawing (drawing.hpp) for scoring it against a picture —
// which pixels the drawing covers, nothing about colour.
//
// The frame (RasterFrame): pixel (i, j) has its centre at user units (originX + (i + 0.5) / ppu,
// originY + (j + 0.5) / ppu) (centreX, centreY); row 0 is the top (SVG's y points down).
//
// Coverage rule: a pixel is covered exactly when its CENTRE is inside the union of the painted
// regions of the drawing's shapes. A shape (read by styleOf, shape_style.hpp, and outlineOf,
// shape_outline.hpp) paints its fill region when fill is not 'none' (a Line has none), and its
// stroke region when stroke is not 'none' and stroke-width > 0; opacity, fill-opacity or
// stroke-opacity 0, display:none and visibility:hidden paint nothing of what they govern. Colour
// does not matter (any paint covers); filters, stroke-dasharray (a dashed stroke covers as a
// solid one), a rect's rx/ry and transforms other than an image's rotation are ignored. An Image
// covers its whole rotated rectangle (centre, width x height, `rotation` degrees clockwise on the
// page). The Drawing's defaults apply (an untagged vertex: circle r 0.4cm, stroke-width 1mm,
// stroke black, fill none -> an annulus; an edge: a line of stroke-width 1mm, butt caps).
//   Circle: fill dx*dx + dy*dy <= r*r; stroke: dx*dx + dy*dy <= (r+h)*(r+h) and not
//     (r - h > 0 and dx*dx + dy*dy < (r-h)*(r-h)), h = stroke-width / 2, d = centre - circle centre.
//   Line, Rect, Path: the polylines of outlineOf (Béziers flattened to kFlatteningTolerancePixels:
//     every point of a curve within 0.05 pixel of the polyline, which then IS the shape).
//     Fill: every subpath implicitly closed; the winding number at the centre (x, y) is the sum,
//     over the edges p -> q with min(p.y, q.y) <= y < max(p.y, q.y), of +1 (p.y < q.y) or -1 whose
//     crossing X = lo.x + (y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y) (lo, hi: the end with the
//     smaller, larger y) has X <= x; covered when it is nonzero (fill-rule nonzero) or odd
//     (evenodd). Stroke: the union of the pieces of stroke_pieces.hpp (bodies, butt/round/square
//     caps, miter joins with stroke-miterlimit, beyond it bevel, round and bevel joins; a closed
//     subpath joined at its first point).
//
// How it is exact: each row is settled with the point tests above, evaluated on the same centre
// coordinates with the same arithmetic (-ffp-contract=off: no fused multiply-add). A piece's half-
// planes and a disc's test are monotone along a row (IEEE rounding is monotone), so a piece covers
// one run of pixels per row, whose ends are found by searching with the test itself (galloping
// from the analytic estimate, then bisection), never by trusting a computed intersection. The fill
// computes each crossing X once and finds the first pixel whose centre x >= X by the same search.
// So the raster equals a brute-force evaluation of the rule at every pixel centre — with one
// proviso: a piece is looked for only in the rows of its box grown by one pixel, which holds
// unless coordinates are so large that rounding reaches a pixel (|x| * 1e-16 >= 1 / ppu).
//
// Bits: row j starts at word j * wordsPerRow() (wordsPerRow = (width + 63) / 64), bit i of the
// row is pixel x = i; bits past the width are 0 (as ImageTarget's rows, score/image/
// image_target.hpp). A DrawingRaster keeps the bits and every scratch buffer: rasterizing
// allocates nothing once warm (same frame, drawings of similar size).
#pragma once
#include <cstdint>
#include <vector>

#include "graph/drawing.hpp"
#include "graph/shape_outline.hpp"
#include "graph/stroke_pieces.hpp"

namespace shapevo::graph {

/// The largest distance between a Bézier and its polyline, in pixels.
inline constexpr double kFlatteningTolerancePixels = 0.05;

struct RasterFrame {
    double originX = 0, originY = 0;  ///< user units of the top-left corner of pixel (0, 0)
    double pixelsPerUnit = 1;         ///< pixels per SVG user unit (> 0)
    int width = 0, height = 0;        ///< pixels

    double centreX(int i) const { return originX + (i + 0.5) / pixelsPerUnit; }
    double centreY(int j) const { return originY + (j + 0.5) / pixelsPerUnit; }
    int wordsPerRow() const { return (width + 63) / 64; }
};

/// The frame showing `canvas` in width x height pixels as the PNG painter fits it: uniform scale,
/// centred (xMidYMid meet); a canvas without width or height gets scale 1 on that side.
RasterFrame frameFitting(const DrawingCanvas& canvas, int width, int height);

class DrawingRaster {
public:
    /// Rasterizes `drawing` into `frame` (replacing what was there); returns the covered pixels.
    std::int64_t rasterize(const Drawing& drawing, const RasterFrame& frame);

    const RasterFrame& frame() const { return frame_; }
    const std::vector<std::uint64_t>& bits() const { return bits_; }
    std::int64_t coveredPixels() const { return covered_; }
    bool covered(int i, int j) const {
        return (bits_[std::size_t(j) * std::size_t(frame_.wordsPerRow()) + std::size_t(i >> 6)] >> (i & 63)) & 1;
    }

    /// A fill edge, its rows [rowBegin, rowEnd) (centres with lo.y <= y < hi.y).
    struct Edge {
        Vec2 lo, hi;
        int direction = 1;
        int rowBegin = 0, rowEnd = 0;
    };
    struct Crossing {
        int pixel = 0;  ///< the first pixel whose centre x >= the crossing
        int direction = 1;
    };

private:
    void paintShape(const Shape& shape);
    void fillPolylines(FillRule rule);
    void fillRow(int j, FillRule rule);
    void paintConvex(const ConvexPiece& piece);
    void paintDisc(Vec2 centre, double radius, double innerRadius);
    void setRun(int j, int from, int to);

    RasterFrame frame_;
    std::vector<std::uint64_t> bits_;
    std::int64_t covered_ = 0;
    PathData path_;
    ShapeOutline outline_;
    StrokePieces pieces_;
    std::vector<Edge> edges_;
    std::vector<std::uint32_t> active_;
    std::vector<Crossing> crossings_;
};

}  // namespace shapevo::graph
