// PlotPainter: the few drawing operations a plot needs (lines, filled shapes, text), so that one
// layout draws the same picture into an SVG document (report/svg_painter.hpp) and into pixels
// (report/cairo_painter.hpp). Coordinates are pixels (SVG user units), y down, origin top left.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace shapevo {

/// sRGB 0..255 and an opacity 0..1.
struct PlotColour {
    int r = 0, g = 0, b = 0;
    double opacity = 1;
};

enum class TextAnchor { Start, Middle, End };

struct PlotText {
    double size = 12;          ///< font size in pixels
    TextAnchor anchor = TextAnchor::Start;
    bool bold = false;
    bool vertical = false;     ///< rotated a quarter turn anticlockwise (reads bottom to top)
    PlotColour colour;
};

class PlotPainter {
public:
    using Points = std::vector<std::pair<double, double>>;
    virtual ~PlotPainter() = default;
    /// `name` tags the element for readers of the SVG (class="name"); pixels ignore it.
    virtual void polyline(const Points& points, PlotColour colour, double width, bool dashed, const std::string& name) = 0;
    virtual void polygon(const Points& points, PlotColour fill, const std::string& name) = 0;
    virtual void rect(double x, double y, double w, double h, PlotColour fill) = 0;
    virtual void circle(double x, double y, double radius, PlotColour fill) = 0;
    /// `text` at (x, y): y is the baseline; x is its start, middle or end per the anchor.
    virtual void text(double x, double y, const std::string& text, const PlotText& style) = 0;
    /// Width of `text` in pixels at `size` (the same measure for both painters: cairo's).
    virtual double textWidth(const std::string& text, double size, bool bold) = 0;

    void line(double x0, double y0, double x1, double y1, PlotColour colour, double width = 1, bool dashed = false) {
        polyline({{x0, y0}, {x1, y1}}, colour, width, dashed, "");
    }
};

}  // namespace shapevo
