// Graph pictures with cairo (graph_picture.hpp): each shape's outline in user units under the
// canvas-to-picture transform, then its fill and its stroke, grouped when `opacity` < 1.
#include "report/graph_picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "graph/path_data.hpp"
#include "graph/shape_style.hpp"
#include "graph/svg_paint.hpp"
#include "image/png_writer.hpp"

namespace shapevo {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace graph_picture_parts {

using graph::Shape;
using graph::ShapeKind;

constexpr double kPi = 3.14159265358979323846;

/// A model point in user units (y down).
graph::Vec2 user(graph::Vec2 p) { return {p.x * graph::kUserUnitsPerModelUnit, -(p.y * graph::kUserUnitsPerModelUnit)}; }

template <class T, class Parse>
std::optional<T> attributeValue(const Shape& s, const char* name, Parse parse) {
    const std::string* text = s.attribute(name);
    if (!text) return std::nullopt;
    return parse(*text);
}

void addPath(cairo_t* cr, const std::string& d) {
    for (const graph::PathSegment& seg : graph::parsePathData(d).segments) {
        switch (seg.op) {
        case graph::PathSegment::Op::Move: cairo_move_to(cr, seg.p[0].x, seg.p[0].y); break;
        case graph::PathSegment::Op::Line: cairo_line_to(cr, seg.p[0].x, seg.p[0].y); break;
        case graph::PathSegment::Op::Quad: {  // the same curve as a cubic
            double x0 = 0, y0 = 0;
            cairo_get_current_point(cr, &x0, &y0);
            const graph::Vec2 q = seg.p[0], e = seg.p[1];
            cairo_curve_to(cr, x0 + 2.0 / 3 * (q.x - x0), y0 + 2.0 / 3 * (q.y - y0), e.x + 2.0 / 3 * (q.x - e.x),
                           e.y + 2.0 / 3 * (q.y - e.y), e.x, e.y);
            break;
        }
        case graph::PathSegment::Op::Cubic:
            cairo_curve_to(cr, seg.p[0].x, seg.p[0].y, seg.p[1].x, seg.p[1].y, seg.p[2].x, seg.p[2].y);
            break;
        case graph::PathSegment::Op::Close: cairo_close_path(cr); break;
        }
    }
}

/// The shape's outline as cairo's current path; false if it has none (SVG: not rendered).
bool addOutline(cairo_t* cr, const Shape& s) {
    switch (s.kind) {
    case ShapeKind::Circle: {
        const double r = attributeValue<double>(s, "r", graph::parseLength).value_or(0);
        if (!(r > 0)) return false;
        const graph::Vec2 c = user(s.centre);
        cairo_new_sub_path(cr);
        cairo_arc(cr, c.x, c.y, r, 0, 2 * kPi);
        cairo_close_path(cr);
        return true;
    }
    case ShapeKind::Line: {
        const graph::Vec2 a = user(s.end1), b = user(s.end2);
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
        return true;
    }
    case ShapeKind::Rect:
    case ShapeKind::Image: {
        if (!(s.width > 0) || !(s.height > 0)) return false;
        const double k = graph::kUserUnitsPerModelUnit;
        const graph::Vec2 c = user(s.centre);
        cairo_save(cr);
        cairo_translate(cr, c.x, c.y);
        if (s.kind == ShapeKind::Image) cairo_rotate(cr, s.rotation * kPi / 180);  // SVG's rotate(): clockwise, y down
        cairo_rectangle(cr, -s.width * k / 2, -s.height * k / 2, s.width * k, s.height * k);
        cairo_restore(cr);  // the path keeps its device coordinates
        return true;
    }
    case ShapeKind::Path: {
        const std::string* d = s.attribute("d");
        if (!d) return false;
        addPath(cr, *d);
        return true;
    }
    }
    return false;
}

/// What SVG reads from the shape's attributes (graph/shape_style.hpp) and its dashes.
struct Look {
    graph::ShapeStyle style;
    std::vector<double> dashes;
};

/// stroke-dasharray: lengths separated by commas or spaces; 'none', a negative length or all
/// zeros: no dashes (SVG); an odd count is repeated.
std::vector<double> parseDashes(const std::string& text) {
    std::vector<double> out;
    std::string item;
    double sum = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        const char c = i < text.size() ? text[i] : ',';
        if (c == ',' || c == ' ' || c == '\t') {
            if (item.empty()) continue;
            const std::optional<double> v = graph::parseLength(item);
            if (!v || *v < 0) return {};
            out.push_back(*v);
            sum += *v;
            item.clear();
        } else {
            item += c;
        }
    }
    if (!(sum > 0)) return {};
    if (out.size() % 2) out.insert(out.end(), out.begin(), out.end());
    return out;
}

cairo_line_cap_t cairoCap(graph::LineCap c) {
    return c == graph::LineCap::Round ? CAIRO_LINE_CAP_ROUND : c == graph::LineCap::Square ? CAIRO_LINE_CAP_SQUARE : CAIRO_LINE_CAP_BUTT;
}
cairo_line_join_t cairoJoin(graph::LineJoin j) {
    return j == graph::LineJoin::Round ? CAIRO_LINE_JOIN_ROUND : j == graph::LineJoin::Bevel ? CAIRO_LINE_JOIN_BEVEL : CAIRO_LINE_JOIN_MITER;
}

Look lookOf(const Shape& s) {
    Look l{graph::styleOf(s), {}};
    if (const std::string* d = s.attribute("stroke-dasharray")) l.dashes = parseDashes(*d);
    return l;
}

void paintShape(cairo_t* cr, const Shape& s) {
    const Look look = lookOf(s);
    const graph::ShapeStyle& l = look.style;
    if (!l.visible()) return;
    if (s.kind == ShapeKind::Image) {  // a placeholder: the image file is not read
        if (!addOutline(cr, s)) return;
        cairo_set_source_rgba(cr, 0.75, 0.75, 0.75, 0.5 * l.opacity);
        cairo_fill_preserve(cr);
        cairo_set_source_rgba(cr, 0.5, 0.5, 0.5, l.opacity);
        cairo_set_line_width(cr, 1);
        cairo_stroke(cr);
        return;
    }
    const bool group = l.opacity < 1;
    if (group) cairo_push_group(cr);
    if (addOutline(cr, s)) {
        if (l.paintsFill()) {
            cairo_set_fill_rule(cr, l.fillRule == graph::FillRule::EvenOdd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
            cairo_set_source_rgba(cr, l.fill.r, l.fill.g, l.fill.b, l.fillOpacity);
            cairo_fill_preserve(cr);
        }
        if (l.paintsStroke()) {
            cairo_set_source_rgba(cr, l.stroke.r, l.stroke.g, l.stroke.b, l.strokeOpacity);
            cairo_set_line_width(cr, l.strokeWidth);
            cairo_set_line_cap(cr, cairoCap(l.cap));
            cairo_set_line_join(cr, cairoJoin(l.join));
            cairo_set_miter_limit(cr, l.miterLimit);
            cairo_set_dash(cr, look.dashes.data(), int(look.dashes.size()), 0);
            cairo_stroke_preserve(cr);
        }
    }
    cairo_new_path(cr);
    if (group) {
        cairo_pop_group_to_source(cr);
        cairo_paint_with_alpha(cr, l.opacity);
    }
}

/// The canvas-to-picture transform: uniform scale, centred (xMidYMid meet).
void fitCanvas(cairo_t* cr, const graph::DrawingCanvas& c, PictureSize size) {
    double scale = 1;
    if (c.width > 0 && c.height > 0) scale = std::min(size.width / c.width, size.height / c.height);
    else if (c.width > 0) scale = size.width / c.width;
    else if (c.height > 0) scale = size.height / c.height;
    cairo_translate(cr, (size.width - c.width * scale) / 2, (size.height - c.height * scale) / 2);
    cairo_scale(cr, scale, scale);
    cairo_translate(cr, -c.x, -c.y);
}

}  // namespace graph_picture_parts

PictureSize naturalPictureSize(const graph::DrawingCanvas& c) {
    double w = std::max(c.width, 0.0), h = std::max(c.height, 0.0);
    double shrink = 1;
    if (w > kMaxPictureSide) shrink = std::min(shrink, kMaxPictureSide / w);
    if (h > kMaxPictureSide) shrink = std::min(shrink, kMaxPictureSide / h);
    if (w * h * shrink * shrink > double(kMaxPicturePixels)) shrink = std::min(shrink, std::sqrt(double(kMaxPicturePixels) / (w * h)));
    auto side = [&](double v) { return std::clamp(int(std::ceil(v * shrink - 1e-9)), 16, kMaxPictureSide); };
    return {side(w), side(h)};
}

std::vector<std::uint8_t> paintDrawing(const graph::Drawing& drawing, const graph::DrawingCanvas& canvas, PictureSize size) {
    using namespace graph_picture_parts;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size.width, size.height);
    cairo_t* cr = cairo_create(surface);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        const std::string why = cairo_status_to_string(cairo_status(cr));
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
        throw std::runtime_error("cairo: cannot make a " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                 " image: " + why);
    }
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    fitCanvas(cr, canvas, size);
    for (const Shape& s : drawing.shapes) paintShape(cr, s);
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    // ARGB32 is premultiplied, native-endian words; the background is opaque, so is every pixel.
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    std::vector<std::uint8_t> rgba(std::size_t(size.width) * std::size_t(size.height) * 4);
    for (int y = 0; y < size.height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
        for (int x = 0; x < size.width; ++x) {
            const std::uint32_t p = row[x];
            std::uint8_t* o = &rgba[(std::size_t(y) * std::size_t(size.width) + std::size_t(x)) * 4];
            o[0] = std::uint8_t(p >> 16);
            o[1] = std::uint8_t(p >> 8);
            o[2] = std::uint8_t(p);
            o[3] = std::uint8_t(p >> 24);
        }
    }
    cairo_surface_destroy(surface);
    return rgba;
}

void writeDrawingPng(const graph::Drawing& drawing, const graph::DrawingCanvas& canvas, PictureSize size,
                     const std::string& path) {
    const std::vector<std::uint8_t> rgba = paintDrawing(drawing, canvas, size);
    writePngRgba(path, size.width, size.height, rgba);
}

}  // namespace shapevo
