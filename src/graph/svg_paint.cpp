// parseLength, parsePaint, parseOpacity (svg_paint.hpp). The named colours are CSS Color
// Module Level 4's table, sorted by name for a binary search.
#include "graph/svg_paint.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace svg_paint_parts {

struct NamedColour {
    std::string_view name;
    std::uint32_t rgb;
};

constexpr NamedColour kNamedColours[] = {
    {"aliceblue", 0xf0f8ff}, {"antiquewhite", 0xfaebd7}, {"aqua", 0x00ffff}, {"aquamarine", 0x7fffd4},
    {"azure", 0xf0ffff}, {"beige", 0xf5f5dc}, {"bisque", 0xffe4c4}, {"black", 0x000000}, {"blanchedalmond", 0xffebcd},
    {"blue", 0x0000ff}, {"blueviolet", 0x8a2be2}, {"brown", 0xa52a2a}, {"burlywood", 0xdeb887},
    {"cadetblue", 0x5f9ea0}, {"chartreuse", 0x7fff00}, {"chocolate", 0xd2691e}, {"coral", 0xff7f50},
    {"cornflowerblue", 0x6495ed}, {"cornsilk", 0xfff8dc}, {"crimson", 0xdc143c}, {"cyan", 0x00ffff},
    {"darkblue", 0x00008b}, {"darkcyan", 0x008b8b}, {"darkgoldenrod", 0xb8860b}, {"darkgray", 0xa9a9a9},
    {"darkgreen", 0x006400}, {"darkgrey", 0xa9a9a9}, {"darkkhaki", 0xbdb76b}, {"darkmagenta", 0x8b008b},
    {"darkolivegreen", 0x556b2f}, {"darkorange", 0xff8c00}, {"darkorchid", 0x9932cc}, {"darkred", 0x8b0000},
    {"darksalmon", 0xe9967a}, {"darkseagreen", 0x8fbc8f}, {"darkslateblue", 0x483d8b}, {"darkslategray", 0x2f4f4f},
    {"darkslategrey", 0x2f4f4f}, {"darkturquoise", 0x00ced1}, {"darkviolet", 0x9400d3}, {"deeppink", 0xff1493},
    {"deepskyblue", 0x00bfff}, {"dimgray", 0x696969}, {"dimgrey", 0x696969}, {"dodgerblue", 0x1e90ff},
    {"firebrick", 0xb22222}, {"floralwhite", 0xfffaf0}, {"forestgreen", 0x228b22}, {"fuchsia", 0xff00ff},
    {"gainsboro", 0xdcdcdc}, {"ghostwhite", 0xf8f8ff}, {"gold", 0xffd700}, {"goldenrod", 0xdaa520}, {"gray", 0x808080},
    {"green", 0x008000}, {"greenyellow", 0xadff2f}, {"grey", 0x808080}, {"honeydew", 0xf0fff0}, {"hotpink", 0xff69b4},
    {"indianred", 0xcd5c5c}, {"indigo", 0x4b0082}, {"ivory", 0xfffff0}, {"khaki", 0xf0e68c}, {"lavender", 0xe6e6fa},
    {"lavenderblush", 0xfff0f5}, {"lawngreen", 0x7cfc00}, {"lemonchiffon", 0xfffacd}, {"lightblue", 0xadd8e6},
    {"lightcoral", 0xf08080}, {"lightcyan", 0xe0ffff}, {"lightgoldenrodyellow", 0xfafad2}, {"lightgray", 0xd3d3d3},
    {"lightgreen", 0x90ee90}, {"lightgrey", 0xd3d3d3}, {"lightpink", 0xffb6c1}, {"lightsalmon", 0xffa07a},
    {"lightseagreen", 0x20b2aa}, {"lightskyblue", 0x87cefa}, {"lightslategray", 0x778899},
    {"lightslategrey", 0x778899}, {"lightsteelblue", 0xb0c4de}, {"lightyellow", 0xffffe0}, {"lime", 0x00ff00},
    {"limegreen", 0x32cd32}, {"linen", 0xfaf0e6}, {"magenta", 0xff00ff}, {"maroon", 0x800000},
    {"mediumaquamarine", 0x66cdaa}, {"mediumblue", 0x0000cd}, {"mediumorchid", 0xba55d3}, {"mediumpurple", 0x9370db},
    {"mediumseagreen", 0x3cb371}, {"mediumslateblue", 0x7b68ee}, {"mediumspringgreen", 0x00fa9a},
    {"mediumturquoise", 0x48d1cc}, {"mediumvioletred", 0xc71585}, {"midnightblue", 0x191970}, {"mintcream", 0xf5fffa},
    {"mistyrose", 0xffe4e1}, {"moccasin", 0xffe4b5}, {"navajowhite", 0xffdead}, {"navy", 0x000080},
    {"oldlace", 0xfdf5e6}, {"olive", 0x808000}, {"olivedrab", 0x6b8e23}, {"orange", 0xffa500}, {"orangered", 0xff4500},
    {"orchid", 0xda70d6}, {"palegoldenrod", 0xeee8aa}, {"palegreen", 0x98fb98}, {"paleturquoise", 0xafeeee},
    {"palevioletred", 0xdb7093}, {"papayawhip", 0xffefd5}, {"peachpuff", 0xffdab9}, {"peru", 0xcd853f},
    {"pink", 0xffc0cb}, {"plum", 0xdda0dd}, {"powderblue", 0xb0e0e6}, {"purple", 0x800080},
    {"rebeccapurple", 0x663399}, {"red", 0xff0000}, {"rosybrown", 0xbc8f8f}, {"royalblue", 0x4169e1},
    {"saddlebrown", 0x8b4513}, {"salmon", 0xfa8072}, {"sandybrown", 0xf4a460}, {"seagreen", 0x2e8b57},
    {"seashell", 0xfff5ee}, {"sienna", 0xa0522d}, {"silver", 0xc0c0c0}, {"skyblue", 0x87ceeb}, {"slateblue", 0x6a5acd},
    {"slategray", 0x708090}, {"slategrey", 0x708090}, {"snow", 0xfffafa}, {"springgreen", 0x00ff7f},
    {"steelblue", 0x4682b4}, {"tan", 0xd2b48c}, {"teal", 0x008080}, {"thistle", 0xd8bfd8}, {"tomato", 0xff6347},
    {"turquoise", 0x40e0d0}, {"violet", 0xee82ee}, {"wheat", 0xf5deb3}, {"white", 0xffffff}, {"whitesmoke", 0xf5f5f5},
    {"yellow", 0xffff00}, {"yellowgreen", 0x9acd32},
};

std::string_view trimmed(std::string_view t) {
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    return t;
}

std::string lowered(std::string_view t) {
    std::string s(t);
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// A leading number of `t` (the rest in `unit`); false if `t` does not start with one.
bool leadingNumber(std::string_view t, double& value, std::string_view& unit) {
    std::size_t from = 0;
    if (!t.empty() && t[0] == '+') from = 1;
    const auto [end, ec] = std::from_chars(t.data() + from, t.data() + t.size(), value);
    if (ec != std::errc() || !std::isfinite(value)) return false;
    unit = t.substr(std::size_t(end - t.data()));
    return true;
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

Paint fromRgb(std::uint32_t rgb) { return {false, ((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0}; }

std::optional<Paint> hexPaint(std::string_view h) {
    if (h.size() != 3 && h.size() != 6) return std::nullopt;
    std::uint32_t rgb = 0;
    for (char c : h)
        if (hexDigit(c) < 0) return std::nullopt;
    if (h.size() == 3)
        for (char c : h) rgb = (rgb << 8) | std::uint32_t(hexDigit(c) * 17);
    else
        for (char c : h) rgb = (rgb << 4) | std::uint32_t(hexDigit(c));
    return fromRgb(rgb);
}

/// rgb(r, g, b): three numbers 0..255 or three percentages, clamped.
std::optional<Paint> functionalPaint(std::string_view args) {
    double channel[3];
    for (int k = 0; k < 3; ++k) {
        args = trimmed(args);
        std::string_view unit;
        if (!leadingNumber(args, channel[k], unit)) return std::nullopt;
        unit = trimmed(unit);
        const bool percent = !unit.empty() && unit[0] == '%';
        if (percent) unit = trimmed(unit.substr(1));
        channel[k] = std::clamp(percent ? channel[k] / 100 : channel[k] / 255, 0.0, 1.0);
        if (k < 2) {
            if (unit.empty() || unit[0] != ',') return std::nullopt;
            args = unit.substr(1);
        } else if (!unit.empty()) {
            return std::nullopt;
        }
    }
    return Paint{false, channel[0], channel[1], channel[2]};
}

}  // namespace svg_paint_parts

std::optional<double> parseLength(std::string_view text) {
    using namespace svg_paint_parts;
    double v = 0;
    std::string_view unit;
    if (!leadingNumber(trimmed(text), v, unit)) return std::nullopt;
    const std::string u = lowered(unit);
    if (u.empty() || u == "px") return v;
    if (u == "in") return v * 96;
    if (u == "cm") return v * 96 / 2.54;
    if (u == "mm") return v * 96 / 25.4;
    if (u == "q") return v * 96 / 101.6;
    if (u == "pt") return v * 96 / 72;
    if (u == "pc") return v * 16;
    return std::nullopt;
}

std::optional<Paint> parsePaint(std::string_view text) {
    using namespace svg_paint_parts;
    // Lower case in a stack buffer (no allocation for any colour text up to 64 characters).
    const std::string_view given = trimmed(text);
    char buffer[64];
    std::string longText;
    std::string_view t;
    if (given.size() <= sizeof buffer) {
        for (std::size_t i = 0; i < given.size(); ++i) buffer[i] = char(std::tolower(static_cast<unsigned char>(given[i])));
        t = std::string_view(buffer, given.size());
    } else {
        longText = lowered(given);
        t = longText;
    }
    if (t == "none" || t == "transparent") return Paint{true};
    if (t == "currentcolor") return Paint{};
    if (!t.empty() && t[0] == '#') return hexPaint(t.substr(1));
    if (t.starts_with("rgb(") && t.back() == ')') return functionalPaint(t.substr(4, t.size() - 5));
    const auto it = std::lower_bound(std::begin(kNamedColours), std::end(kNamedColours), t,
                                     [](const NamedColour& c, std::string_view n) { return c.name < n; });
    if (it != std::end(kNamedColours) && it->name == t) return fromRgb(it->rgb);
    return std::nullopt;
}

std::optional<double> parseOpacity(std::string_view text) {
    using namespace svg_paint_parts;
    double v = 0;
    std::string_view unit;
    if (!leadingNumber(trimmed(text), v, unit)) return std::nullopt;
    unit = trimmed(unit);
    if (unit == "%") v /= 100;
    else if (!unit.empty()) return std::nullopt;
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace shapevo::graph
