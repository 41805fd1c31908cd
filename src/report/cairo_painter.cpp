// CairoPainter: straight calls into cairo; the PNG goes through cairo's stream writer into an
// atomically published file.
#include "report/cairo_painter.hpp"

#include <cairo.h>

#include <ostream>
#include <stdexcept>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"

namespace shapevo {

CairoPainter::CairoPainter(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height)), cr_(cairo_create(surface_)) {
    if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
        const std::string why = cairo_status_to_string(cairo_status(cr_));
        cairo_destroy(cr_);
        cairo_surface_destroy(surface_);
        throw std::runtime_error("cairo: cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " image: " + why);
    }
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_paint(cr_);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
}

CairoPainter::~CairoPainter() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
}

void CairoPainter::setColour(PlotColour c) { cairo_set_source_rgba(cr_, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.opacity); }

void CairoPainter::setFont(double size, bool bold) {
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, size);
}

void CairoPainter::polyline(const Points& points, PlotColour colour, double width, bool dashed, const std::string&) {
    if (points.empty()) return;
    cairo_move_to(cr_, points[0].first, points[0].second);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i].first, points[i].second);
    static const double dash[] = {6, 3};
    cairo_set_dash(cr_, dash, dashed ? 2 : 0, 0);
    cairo_set_line_width(cr_, width);
    setColour(colour);
    cairo_stroke(cr_);
    cairo_set_dash(cr_, dash, 0, 0);
}

void CairoPainter::polygon(const Points& points, PlotColour fill, const std::string&) {
    if (points.empty()) return;
    cairo_move_to(cr_, points[0].first, points[0].second);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i].first, points[i].second);
    cairo_close_path(cr_);
    setColour(fill);
    cairo_fill(cr_);
}

void CairoPainter::rect(double x, double y, double w, double h, PlotColour fill) {
    cairo_rectangle(cr_, x, y, w, h);
    setColour(fill);
    cairo_fill(cr_);
}

void CairoPainter::circle(double x, double y, double radius, PlotColour fill) {
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, x, y, radius, 0, 6.283185307179586);
    setColour(fill);
    cairo_fill(cr_);
}

void CairoPainter::text(double x, double y, const std::string& text, const PlotText& style) {
    setFont(style.size, style.bold);
    cairo_text_extents_t e;
    cairo_text_extents(cr_, text.c_str(), &e);
    const double shift = style.anchor == TextAnchor::Start ? 0 : style.anchor == TextAnchor::Middle ? e.x_advance / 2 : e.x_advance;
    cairo_save(cr_);
    cairo_translate(cr_, x, y);
    if (style.vertical) cairo_rotate(cr_, -1.5707963267948966);
    cairo_move_to(cr_, -shift, 0);
    setColour(style.colour);
    cairo_show_text(cr_, text.c_str());
    cairo_restore(cr_);
}

double CairoPainter::textWidth(const std::string& text, double size, bool bold) {
    setFont(size, bold);
    cairo_text_extents_t e;
    cairo_text_extents(cr_, text.c_str(), &e);
    return e.x_advance;
}

void CairoPainter::writePng(const std::string& path) {
    cairo_surface_flush(surface_);
    writeStreamAtomically(path, [&](std::ostream& out) {
        const cairo_status_t status = cairo_surface_write_to_png_stream(
            surface_,
            [](void* closure, const unsigned char* data, unsigned int length) {
                std::ostream& o = *static_cast<std::ostream*>(closure);
                o.write(reinterpret_cast<const char*>(data), std::streamsize(length));
                return o ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
            },
            &out);
        if (status != CAIRO_STATUS_SUCCESS)
            throw InputError(path, "", std::string("cannot write the PNG: ") + cairo_status_to_string(status));
    });
}

}  // namespace shapevo
