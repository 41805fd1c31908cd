// Drawing: what the original's SVG exporter draws for a host graph (graph-grammar README,
// section 4), as plain data — one Shape per drawn element in breadthFirstOrder (the z-order), its
// geometry in model units (y up) and its SVG attributes (the defaults of its kind, replaced or
// extended by the element's `.svg_<name>` attributes). The SVG writer (svg_writer.hpp) and the
// PNG painter (report/graph_picture.hpp) both draw from it alone, so they agree; a rasterizer
// for scoring (drawing_raster.hpp) reads it the same way. The same graph gives the same Drawing, byte for byte.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "graph/host_graph.hpp"
#include "graph/value.hpp"

namespace shapevo::graph {

/// SVG user units per model unit: the original's 1 cm at 90 dpi (its constant, as written).
inline constexpr double kUserUnitsPerModelUnit = 35.43307;
/// A `rect` tag's width and height when the element gives none (model units), and an `image`'s.
inline constexpr double kDefaultRectSize = 0.1;
inline constexpr double kDefaultImageSize = 5;

enum class ShapeKind : std::uint8_t {
    Circle,  ///< centred on `centre`; its radius is the attribute `r` (a CSS length)
    Line,    ///< from `end1` to `end2`
    Rect,    ///< centred on `centre`, `width` x `height`
    Path,    ///< the attribute `d`, already in SVG user units (y down), placed nowhere else
    Image,   ///< centred on `centre`, `width` x `height`, turned by `rotation` degrees about its centre
};

/// One SVG attribute as the SVG file writes it: name (e.g. "stroke-width") and value text.
struct DrawAttribute {
    std::string name, value;
    friend bool operator==(const DrawAttribute&, const DrawAttribute&) = default;
};

struct Shape {
    ShapeKind kind = ShapeKind::Circle;
    DrawItem element{true, 0};     ///< the graph element it draws
    Vec2 centre;                   ///< Circle, Rect, Image (model units)
    Vec2 end1, end2;               ///< Line (model units)
    double width = 0, height = 0;  ///< Rect, Image (model units)
    /// Image: degrees, as SVG's rotate() turns (clockwise on the page, whose y points down).
    double rotation = 0;
    /// Every attribute but the geometry the writer derives from the fields above (circle cx/cy,
    /// line x1..y2, rect and image x/y/width/height, the image's transform), sorted by name.
    /// Circle has `r`, Path has `d`, Image has `xlink:href` when the element gives one.
    std::vector<DrawAttribute> attributes;

    /// The value of attribute `name`, or nullptr.
    const std::string* attribute(const std::string& name) const {
        for (const DrawAttribute& a : attributes)
            if (a.name == name) return &a.value;
        return nullptr;
    }
};

struct Drawing {
    std::vector<Shape> shapes;  ///< in drawing (z-)order
    /// The bounding box of the live vertices' positions (model units), the original's canvas;
    /// hasVertices = false (a graph with no vertex) leaves it at 0.
    bool hasVertices = false;
    Vec2 min, max;
};

/// The canvas an SVG or PNG shows, in SVG user units (y down): the vertices' box grown by a
/// margin, scaled by kUserUnitsPerModelUnit and flipped. Margin 0 is the original's canvas.
struct DrawingCanvas {
    double x = 0, y = 0, width = 0, height = 0;
};
DrawingCanvas canvasOf(const Drawing& drawing, double marginModelUnits);

/// The shapes of `graph` (whose attribute names are `names`), README section 4:
/// - a vertex without `.svg_tag` is a circle (r 0.4cm, stroke-width 1mm, stroke black, fill none);
///   an edge without one a line between its ends (stroke-width 1mm, stroke black);
/// - `.svg_tag` `circle` (r 1cm, stroke-width 0.1mm), `rect` (`.svg_width`/`.svg_height` in
///   model units, default 0.1), `path` (`.svg_d`), `image` (`.svg_width`/`.svg_height`, default
///   5; `.svgx_rotate` degrees; `.svg_href` becomes `xlink:href`), `line` (edges only: the untagged
///   edge's line); a vertex's
///   shape is centred on it, an edge's on the middle of its ends;
/// - `.svg_tag` None, 'None' or 'none' draws nothing; so does an edge with an empty end (a
///   dangling edge has no place to be drawn), whatever its tag, and a `.helper_node` vertex;
/// - every other `.svg_<name>` is attribute <name> with '_' -> '-' (one trailing '_' dropped, as
///   Python's `in_`), its value as Python's str() writes it; `.svg_filter: 'id'` becomes
///   filter="url(#id)". Geometry attributes (cx, cy, x, y, ...) are the shape's own.
/// @throw InputError naming `source` and the element for an unknown tag, a `line` on a vertex,
/// a width, height or rotation that is not a finite number, or an attribute name that is not an
/// XML name or is an event handler (on...: a script in the picture).
Drawing drawingOf(const HostGraph& graph, const AttrNames& names, const std::string& source);

}  // namespace shapevo::graph
