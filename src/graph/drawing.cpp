// drawingOf: the original exporter's shapes for each element (drawing.hpp states the rules).
// Attribute names are classified once per call (one entry per interned name), so an element
// costs a pass over its own attributes.
#include "graph/drawing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "base/input_error.hpp"
#include "graph/xml_text.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace drawing_parts {

/// What an attribute name means to the exporter.
enum class Role : std::uint8_t { Ignored, Tag, Width, Height, Rotate, HelperNode, Attribute };

struct NameRoles {
    std::vector<Role> roles;         // per AttrKey
    std::vector<std::string> names;  // per AttrKey: the SVG attribute name (Role::Attribute)
};

/// `.svg_stroke_width` -> "stroke-width"; `.svg_in_` -> "in" (Python's keyword escape).
std::string svgAttributeName(std::string_view rest) {
    if (!rest.empty() && rest.back() == '_') rest.remove_suffix(1);
    std::string name(rest);
    std::replace(name.begin(), name.end(), '_', '-');
    if (name == "href") return "xlink:href";
    return name;
}

NameRoles classify(const AttrNames& names) {
    NameRoles r;
    r.roles.assign(names.size(), Role::Ignored);
    r.names.resize(names.size());
    for (AttrKey k = 0; k < names.size(); ++k) {
        const std::string_view n = names.name(k);
        if (n == ".svg_tag") r.roles[k] = Role::Tag;
        else if (n == ".svg_width") r.roles[k] = Role::Width;
        else if (n == ".svg_height") r.roles[k] = Role::Height;
        else if (n == ".svgx_rotate") r.roles[k] = Role::Rotate;
        else if (n == ".helper_node") r.roles[k] = Role::HelperNode;
        else if (n.starts_with(".svg_")) {
            r.roles[k] = Role::Attribute;
            r.names[k] = svgAttributeName(n.substr(5));
        }
    }
    return r;
}

bool isEventHandler(std::string_view n) {
    return n.size() >= 2 && (n[0] == 'o' || n[0] == 'O') && (n[1] == 'n' || n[1] == 'N');
}

/// The geometry attributes a kind's writer derives itself (an element's own are not used).
bool isGeometryOf(ShapeKind kind, std::string_view n) {
    switch (kind) {
    case ShapeKind::Circle: return n == "cx" || n == "cy";
    case ShapeKind::Line: return n == "x1" || n == "y1" || n == "x2" || n == "y2";
    case ShapeKind::Rect: return n == "x" || n == "y" || n == "width" || n == "height";
    case ShapeKind::Image: return n == "x" || n == "y" || n == "width" || n == "height" || n == "transform";
    case ShapeKind::Path: return false;
    }
    return false;
}

void setAttribute(std::vector<DrawAttribute>& list, const std::string& name, std::string value) {
    for (DrawAttribute& a : list)
        if (a.name == name) {
            a.value = std::move(value);
            return;
        }
    list.push_back({name, std::move(value)});
}

std::string elementName(DrawItem item) { return std::string(item.isVertex ? "vertex " : "edge ") + std::to_string(item.id); }

/// A number given as a number or as a string of one ('0.1', as host graphs hold them).
double numberAttribute(const Value& v, DrawItem item, const char* key, const std::string& source) {
    double d = 0;
    bool ok = numberOf(v, d) && !v.asBool();
    if (const std::string* s = v.asString()) {
        std::string_view t = *s;
        while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
        while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
        if (!t.empty() && t.front() == '+') t.remove_prefix(1);
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), d);
        ok = ec == std::errc() && end == t.data() + t.size() && !t.empty();
    }
    if (!ok || !std::isfinite(d))
        throw InputError(source, elementName(item),
                         std::string(key) + " is '" + shortened(toText(v)) + "': the drawing needs a finite number");
    return d;
}

struct ElementLook {
    const Value* tag = nullptr;
    const Value* width = nullptr;
    const Value* height = nullptr;
    const Value* rotate = nullptr;
    bool helper = false;
};

ElementLook lookOf(const AttrMap& attrs, const NameRoles& roles) {
    ElementLook look;
    for (const auto& [key, value] : attrs.entries) {
        if (key >= roles.roles.size()) continue;
        switch (roles.roles[key]) {
        case Role::Tag: look.tag = &value; break;
        case Role::Width: look.width = &value; break;
        case Role::Height: look.height = &value; break;
        case Role::Rotate: look.rotate = &value; break;
        case Role::HelperNode: look.helper = true; break;
        default: break;
        }
    }
    return look;
}

/// The shape kind `tag` names; false for None/'None'/'none' (nothing drawn).
bool kindOfTag(const Value* tag, DrawItem item, const std::string& source, ShapeKind& kind) {
    if (!tag) {
        kind = item.isVertex ? ShapeKind::Circle : ShapeKind::Line;
        return true;
    }
    if (tag->isNone()) return false;
    const std::string text = toText(*tag);
    if (text == "None" || text == "none") return false;
    if (text == "circle") kind = ShapeKind::Circle;
    else if (text == "rect") kind = ShapeKind::Rect;
    else if (text == "path") kind = ShapeKind::Path;
    else if (text == "image") kind = ShapeKind::Image;
    else if (text == "line" && !item.isVertex) kind = ShapeKind::Line;
    else
        throw InputError(source, elementName(item),
                         ".svg_tag is '" + shortened(text) + "': a " + (item.isVertex ? "vertex" : "edge") +
                             " draws as circle, rect, path, image" + (item.isVertex ? "" : ", line") + " or None");
    return true;
}

/// The kind's default attributes (before the element's own replace them).
void addDefaults(Shape& s, bool untagged) {
    if (s.kind == ShapeKind::Circle && untagged)
        s.attributes = {{"fill", "none"}, {"r", "0.4cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}};
    else if (s.kind == ShapeKind::Circle)
        s.attributes = {{"r", "1cm"}, {"stroke-width", "0.1mm"}};
    else if (s.kind == ShapeKind::Line)  // untagged or `line`: the same
        s.attributes = {{"stroke", "black"}, {"stroke-width", "1mm"}};
}

void addOwnAttributes(Shape& s, const AttrMap& attrs, const AttrNames& names, const NameRoles& roles, const std::string& source) {
    const bool sized = s.kind == ShapeKind::Rect || s.kind == ShapeKind::Image;
    for (const auto& [key, value] : attrs.entries) {
        if (key >= roles.roles.size()) continue;
        const Role role = roles.roles[key];
        std::string name;
        if (role == Role::Attribute) name = roles.names[key];
        else if ((role == Role::Width || role == Role::Height) && !sized) name = role == Role::Width ? "width" : "height";
        else continue;
        if (!isXmlName(name) || isEventHandler(name))
            throw InputError(source, elementName(s.element),
                             "attribute '" + shortened(name) + "' (from '" + shortened(names.name(key)) + "') " +
                                 (isXmlName(name) ? "is an event handler: a script in the picture is refused"
                                                  : "is not an XML attribute name"));
        if (isGeometryOf(s.kind, name)) continue;
        std::string text = toText(value);
        if (name == "filter" && !text.starts_with("url(")) text = "url(#" + text + ")";
        setAttribute(s.attributes, name, std::move(text));
    }
    std::sort(s.attributes.begin(), s.attributes.end(),
              [](const DrawAttribute& a, const DrawAttribute& b) { return a.name < b.name; });
}

}  // namespace drawing_parts

DrawingCanvas canvasOf(const Drawing& d, double margin) {
    const double s = kUserUnitsPerModelUnit;
    DrawingCanvas c;
    c.x = (d.min.x - margin) * s;
    c.y = -(d.max.y + margin) * s;
    c.width = (d.max.x - d.min.x + 2 * margin) * s;
    c.height = (d.max.y - d.min.y + 2 * margin) * s;
    return c;
}

Drawing drawingOf(const HostGraph& graph, const AttrNames& names, const std::string& source) {
    using namespace drawing_parts;
    const NameRoles roles = classify(names);
    Drawing drawing;
    for (const HostVertex& v : graph.vertices()) {
        if (!v.alive || lookOf(v.attrs, roles).helper) continue;
        if (!drawing.hasVertices) drawing.min = drawing.max = v.position;
        drawing.hasVertices = true;
        drawing.min = {std::min(drawing.min.x, v.position.x), std::min(drawing.min.y, v.position.y)};
        drawing.max = {std::max(drawing.max.x, v.position.x), std::max(drawing.max.y, v.position.y)};
    }
    for (const DrawItem item : breadthFirstOrder(graph)) {
        const AttrMap& attrs = item.isVertex ? graph.vertex(item.id).attrs : graph.edge(item.id).attrs;
        const ElementLook look = lookOf(attrs, roles);
        Shape s;
        s.element = item;
        if (look.helper || !kindOfTag(look.tag, item, source, s.kind)) continue;
        if (item.isVertex) {
            s.centre = graph.vertex(item.id).position;
        } else {
            const HostEdge& e = graph.edge(item.id);
            if (e.vertex1 == kNoVertex || e.vertex2 == kNoVertex) continue;  // no place to draw it
            s.end1 = graph.vertex(e.vertex1).position;
            s.end2 = graph.vertex(e.vertex2).position;
            s.centre = {(s.end1.x + s.end2.x) / 2, (s.end1.y + s.end2.y) / 2};
        }
        if (s.kind == ShapeKind::Rect || s.kind == ShapeKind::Image) {
            const double fallback = s.kind == ShapeKind::Rect ? kDefaultRectSize : kDefaultImageSize;
            s.width = look.width ? numberAttribute(*look.width, item, ".svg_width", source) : fallback;
            s.height = look.height ? numberAttribute(*look.height, item, ".svg_height", source) : fallback;
        }
        if (s.kind == ShapeKind::Image && look.rotate) s.rotation = numberAttribute(*look.rotate, item, ".svgx_rotate", source);
        addDefaults(s, look.tag == nullptr);
        addOwnAttributes(s, attrs, names, roles, source);
        drawing.shapes.push_back(std::move(s));
    }
    return drawing;
}

}  // namespace shapevo::graph
