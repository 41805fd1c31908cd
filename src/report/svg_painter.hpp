// SvgPainter: a PlotPainter that writes a self-contained SVG document: real <text> elements (so
// titles, labels and numbers can be read, searched and copied), classed shapes, numbers with two
// decimals. Text is measured with cairo, as the PNG painter measures it, so both place labels alike.
#pragma once
#include <string>

#include "report/cairo_painter.hpp"
#include "report/plot_painter.hpp"

namespace shapevo {

class SvgPainter : public PlotPainter {
public:
    /// `title` becomes the document's <title> (what viewers show as its name).
    SvgPainter(int width, int height, const std::string& title);

    void polyline(const Points& points, PlotColour colour, double width, bool dashed, const std::string& name) override;
    void polygon(const Points& points, PlotColour fill, const std::string& name) override;
    void rect(double x, double y, double w, double h, PlotColour fill) override;
    void circle(double x, double y, double radius, PlotColour fill) override;
    void text(double x, double y, const std::string& text, const PlotText& style) override;
    double textWidth(const std::string& text, double size, bool bold) override;

    /// The finished document.
    std::string document() const { return body_ + "</svg>\n"; }

private:
    std::string body_;
    CairoPainter measure_{1, 1};
};

/// `s` with &, <, > and " escaped for XML text and attribute values.
std::string xmlEscape(const std::string& s);

}  // namespace shapevo
