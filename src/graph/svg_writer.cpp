// drawingSvg (svg_writer.hpp): the header and <defs> svgwrite writes, then one element per shape.
#include "graph/svg_writer.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "graph/value_compare.hpp"
#include "graph/xml_text.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace svg_writer_parts {

using Attributes = std::vector<std::pair<std::string, std::string>>;
std::string number(double d) { return toText(Value(d)); }

bool writableName(std::string_view n) {
    return isXmlName(n) && !(n.size() >= 2 && (n[0] == 'o' || n[0] == 'O') && (n[1] == 'n' || n[1] == 'N'));
}

/// An attribute as views into strings that outlive the element's writing (no copy per shape).
using AttributeViews = std::vector<std::pair<std::string_view, std::string_view>>;

/// `<tag a="1" b="2" />` with the attributes sorted by name (svgwrite's order).
void writeElement(std::string& out, std::string_view tag, AttributeViews& attributes, bool close = true) {
    // Insertion sort, stable and without the buffer std::stable_sort allocates (a shape has few).
    for (std::size_t i = 1; i < attributes.size(); ++i)
        for (std::size_t j = i; j > 0 && attributes[j].first < attributes[j - 1].first; --j) std::swap(attributes[j], attributes[j - 1]);
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

void writeElement(std::string& out, std::string_view tag, const Attributes& attributes, bool close = true) {
    AttributeViews views(attributes.begin(), attributes.end());
    writeElement(out, tag, views, close);
}

/// Number texts reused from shape to shape (their capacity stays: no allocation once warm).
struct NumberTexts {
    std::array<std::string, 6> slots;
    std::string transform;
    std::string_view operator()(std::size_t i, double d) {
        slots[i].clear();
        appendFloatRepr(slots[i], d);
        return slots[i];
    }
};

/// Appends the shape's geometry attributes, in user units (y down).
void appendGeometry(const Shape& s, NumberTexts& n, AttributeViews& a) {
    constexpr double k = kUserUnitsPerModelUnit;
    switch (s.kind) {
    case ShapeKind::Circle:
        a.emplace_back("cx", n(0, s.centre.x * k));
        a.emplace_back("cy", n(1, -(s.centre.y * k)));
        return;
    case ShapeKind::Line:
        a.emplace_back("x1", n(0, s.end1.x * k));
        a.emplace_back("x2", n(1, s.end2.x * k));
        a.emplace_back("y1", n(2, -(s.end1.y * k)));
        a.emplace_back("y2", n(3, -(s.end2.y * k)));
        return;
    case ShapeKind::Rect:
    case ShapeKind::Image: {
        a.emplace_back("height", n(0, s.height * k));
        a.emplace_back("width", n(1, s.width * k));
        a.emplace_back("x", n(2, (s.centre.x - s.width / 2) * k));
        a.emplace_back("y", n(3, -((s.centre.y + s.height / 2) * k)));
        if (s.kind == ShapeKind::Image && s.rotation != 0) {
            n.transform = "rotate(" + number(s.rotation) + "," + number(s.centre.x * k) + "," + number(-(s.centre.y * k)) + ")";
            a.emplace_back("transform", n.transform);
        }
        return;
    }
    case ShapeKind::Path: return;
    }
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
        writeElement(out, "filter", Attributes{{"id", f.id}}, false);
        for (const SvgFilter::Primitive& p : f.primitives) {
            if (!writableName(p.tag)) continue;
            Attributes a;
            for (const auto& [given, value] : p.attributes) {
                std::string name = given;
                if (!name.empty() && name.back() == '_') name.pop_back();
                std::replace(name.begin(), name.end(), '_', '-');
                if (writableName(name)) a.emplace_back(std::move(name), value);
            }
            writeElement(out, p.tag, a);
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
                 Attributes{{"baseProfile", "full"},
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
    NumberTexts numbers;
    AttributeViews a;
    for (const Shape& s : drawing.shapes) {
        a.clear();
        appendGeometry(s, numbers, a);
        for (const DrawAttribute& d : s.attributes) a.emplace_back(d.name, d.value);
        writeElement(out, tagOf(s.kind), a);
    }
    out += "</svg>";
    return out;
}

}  // namespace shapevo::graph
