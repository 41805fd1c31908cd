// drawingSvg (svg_writer.hpp): the header and <defs> svgwrite writes, then one element per shape.
#include "graph/svg_writer.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "graph/xml_text.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace svg_writer_parts {

using Attributes = std::vector<std::pair<std::string, std::string>>;

std::string number(double d) { return toText(Value(d)); }

bool writableName(std::string_view n) {
    return isXmlName(n) && !(n.size() >= 2 && (n[0] == 'o' || n[0] == 'O') && (n[1] == 'n' || n[1] == 'N'));
}

/// `<tag a="1" b="2" />` with the attributes sorted by name (svgwrite's order).
void writeElement(std::string& out, std::string_view tag, Attributes attributes, bool close = true) {
    std::stable_sort(attributes.begin(), attributes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    out += '<';
    out += tag;
    for (const auto& [name, value] : attributes) {
        out += ' ';
        out += name;
        out += "=\"";
        appendEscaped(out, value);
        out += '"';
    }
    out += close ? " />" : ">";
}

/// The shape's geometry attributes, in user units (y down).
Attributes geometryOf(const Shape& s) {
    constexpr double k = kUserUnitsPerModelUnit;
    switch (s.kind) {
    case ShapeKind::Circle: return {{"cx", number(s.centre.x * k)}, {"cy", number(-(s.centre.y * k))}};
    case ShapeKind::Line:
        return {{"x1", number(s.end1.x * k)}, {"x2", number(s.end2.x * k)}, {"y1", number(-(s.end1.y * k))}, {"y2", number(-(s.end2.y * k))}};
    case ShapeKind::Rect:
    case ShapeKind::Image: {
        Attributes a{{"height", number(s.height * k)},
                     {"width", number(s.width * k)},
                     {"x", number((s.centre.x - s.width / 2) * k)},
                     {"y", number(-((s.centre.y + s.height / 2) * k))}};
        if (s.kind == ShapeKind::Image && s.rotation != 0)
            a.emplace_back("transform", "rotate(" + number(s.rotation) + "," + number(s.centre.x * k) + "," +
                                            number(-(s.centre.y * k)) + ")");
        return a;
    }
    case ShapeKind::Path: return {};
    }
    return {};
}

const char* tagOf(ShapeKind kind) {
    switch (kind) {
    case ShapeKind::Circle: return "circle";
    case ShapeKind::Line: return "line";
    case ShapeKind::Rect: return "rect";
    case ShapeKind::Path: return "path";
    case ShapeKind::Image: return "image";
    }
    return "g";
}

void writeFilters(std::string& out, std::span<const SvgFilter> filters) {
    if (filters.empty()) {
        out += "<defs />";
        return;
    }
    out += "<defs>";
    for (const SvgFilter& f : filters) {
        writeElement(out, "filter", {{"id", f.id}}, false);
        for (const SvgFilter::Primitive& p : f.primitives) {
            if (!writableName(p.tag)) continue;
            Attributes a;
            for (const auto& [given, value] : p.attributes) {
                std::string name = given;
                if (!name.empty() && name.back() == '_') name.pop_back();
                std::replace(name.begin(), name.end(), '_', '-');
                if (writableName(name)) a.emplace_back(std::move(name), value);
            }
            writeElement(out, p.tag, std::move(a));
        }
        out += "</filter>";
    }
    out += "</defs>";
}

}  // namespace svg_writer_parts

std::string drawingSvg(const Drawing& drawing, std::span<const SvgFilter> filters, const DrawingCanvas& c) {
    using namespace svg_writer_parts;
    std::string out = "<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n";
    out.reserve(out.size() + 512 + drawing.shapes.size() * 160);
    const std::string viewBox = number(c.x) + " " + number(c.y) + " " + number(c.width) + " " + number(c.height);
    writeElement(out, "svg",
                 {{"baseProfile", "full"},
                  {"height", number(c.height)},
                  {"preserveAspectRatio", "xMidYMid meet"},
                  {"version", "1.1"},
                  {"viewBox", viewBox},
                  {"width", number(c.width)},
                  {"xmlns", "http://www.w3.org/2000/svg"},
                  {"xmlns:ev", "http://www.w3.org/2001/xml-events"},
                  {"xmlns:xlink", "http://www.w3.org/1999/xlink"}},
                 false);
    writeFilters(out, filters);
    for (const Shape& s : drawing.shapes) {
        Attributes a = geometryOf(s);
        for (const DrawAttribute& d : s.attributes) a.emplace_back(d.name, d.value);
        writeElement(out, tagOf(s.kind), std::move(a));
    }
    out += "</svg>";
    return out;
}

}  // namespace shapevo::graph
