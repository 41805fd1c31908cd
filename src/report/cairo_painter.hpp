// CairoPainter: a PlotPainter onto a cairo image surface (white background, antialiased, the
// system's sans-serif font), saved as PNG. Also measures text for the SVG painter, so both
// layouts place labels alike.
#pragma once
#include <memory>

#include "report/plot_painter.hpp"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace shapevo {

class CairoPainter : public PlotPainter {
public:
    CairoPainter(int width, int height);
    ~CairoPainter() override;
    CairoPainter(const CairoPainter&) = delete;
    CairoPainter& operator=(const CairoPainter&) = delete;

    void polyline(const Points& points, PlotColour colour, double width, bool dashed, const std::string& name) override;
    void polygon(const Points& points, PlotColour fill, const std::string& name) override;
    void rect(double x, double y, double w, double h, PlotColour fill) override;
    void circle(double x, double y, double radius, PlotColour fill) override;
    void text(double x, double y, const std::string& text, const PlotText& style) override;
    double textWidth(const std::string& text, double size, bool bold) override;

    /// The picture as a PNG at `path`, appearing atomically. @throw InputError naming `path`.
    void writePng(const std::string& path);

private:
    void setColour(PlotColour c);
    void setFont(double size, bool bold);
    cairo_surface_t* surface_ = nullptr;
    cairo_t* cr_ = nullptr;
};

}  // namespace shapevo
