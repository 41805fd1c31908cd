// styleOf (shape_style.hpp): each presentation attribute parsed by svg_paint.hpp, or its default.
#include "graph/shape_style.hpp"

namespace shapevo::graph {

const std::string* attributeOf(const Shape& shape, std::string_view name) {
    for (const DrawAttribute& a : shape.attributes)
        if (a.name == name) return &a.value;
    return nullptr;
}

ShapeStyle styleOf(const Shape& s) {
    ShapeStyle l;
    if (const std::string* t = attributeOf(s, "fill"))
        if (auto p = parsePaint(*t)) l.fill = *p;
    if (const std::string* t = attributeOf(s, "stroke"))
        if (auto p = parsePaint(*t)) l.stroke = *p;
    if (const std::string* t = attributeOf(s, "fill-opacity")) l.fillOpacity = parseOpacity(*t).value_or(1);
    if (const std::string* t = attributeOf(s, "stroke-opacity")) l.strokeOpacity = parseOpacity(*t).value_or(1);
    if (const std::string* t = attributeOf(s, "opacity")) l.opacity = parseOpacity(*t).value_or(1);
    if (const std::string* t = attributeOf(s, "stroke-width"))
        if (auto w = parseLength(*t); w && *w >= 0) l.strokeWidth = *w;
    if (const std::string* m = attributeOf(s, "stroke-miterlimit"))
        if (auto v = parseLength(*m); v && *v >= 1) l.miterLimit = *v;
    if (const std::string* c = attributeOf(s, "stroke-linecap"))
        l.cap = *c == "round" ? LineCap::Round : *c == "square" ? LineCap::Square : LineCap::Butt;
    if (const std::string* j = attributeOf(s, "stroke-linejoin"))
        l.join = *j == "round" ? LineJoin::Round : *j == "bevel" ? LineJoin::Bevel : LineJoin::Miter;
    if (const std::string* r = attributeOf(s, "fill-rule"); r && *r == "evenodd") l.fillRule = FillRule::EvenOdd;
    const std::string* display = attributeOf(s, "display");
    const std::string* visibility = attributeOf(s, "visibility");
    l.hidden = (display && *display == "none") || (visibility && (*visibility == "hidden" || *visibility == "collapse"));
    if (s.kind == ShapeKind::Line) l.fill.none = true;  // a line has no inside
    return l;
}

}  // namespace shapevo::graph
