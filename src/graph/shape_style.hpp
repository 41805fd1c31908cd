// ShapeStyle: how an SVG renderer reads a Shape's presentation attributes — fill, stroke,
// stroke-width, fill-opacity, stroke-opacity, opacity, stroke-linecap, stroke-linejoin,
// stroke-miterlimit, fill-rule, display and visibility — with SVG's defaults for whatever is
// absent or not valid (fill black, stroke none, stroke-width 1, butt caps, miter joins with limit
// 4, nonzero). The PNG painter (report/graph_picture.cpp) and the raster for scoring
// (drawing_raster.hpp) both read a shape through styleOf, so they agree on what is painted.
// styleOf allocates nothing.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "graph/drawing.hpp"
#include "graph/svg_paint.hpp"

namespace shapevo::graph {

enum class LineCap : std::uint8_t { Butt, Round, Square };
enum class LineJoin : std::uint8_t { Miter, Round, Bevel };
enum class FillRule : std::uint8_t { NonZero, EvenOdd };

struct ShapeStyle {
    Paint fill{false, 0, 0, 0};  ///< SVG's initial fill: black
    Paint stroke{true};          ///< SVG's initial stroke: none
    double fillOpacity = 1, strokeOpacity = 1, opacity = 1;
    double strokeWidth = 1;  ///< user units, >= 0
    double miterLimit = 4;   ///< >= 1
    LineCap cap = LineCap::Butt;
    LineJoin join = LineJoin::Miter;
    FillRule fillRule = FillRule::NonZero;
    bool hidden = false;  ///< display:none, visibility:hidden or collapse

    /// Something of the shape is painted at all (not hidden, opacity > 0).
    bool visible() const { return !hidden && opacity > 0; }
    /// Its fill region is painted (a Line has no fill: styleOf sets its fill to none).
    bool paintsFill() const { return visible() && !fill.none && fillOpacity > 0; }
    /// Its stroke region is painted.
    bool paintsStroke() const { return visible() && !stroke.none && strokeOpacity > 0 && strokeWidth > 0; }
};

/// The value of `shape`'s attribute `name`, or nullptr (Shape::attribute without a std::string
/// for the name, so without an allocation for long names such as stroke-miterlimit).
const std::string* attributeOf(const Shape& shape, std::string_view name);

ShapeStyle styleOf(const Shape& shape);

}  // namespace shapevo::graph
