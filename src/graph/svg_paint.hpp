// The values of a Drawing's presentation attributes as an SVG renderer reads them: CSS lengths
// ('1mm', '0.4cm', '3cm', '2px', '1.5' — 96 dpi, so 1in = 96 user units) and colours (the CSS
// named colours, #rgb, #rrggbb, rgb(r, g, b) with numbers or percentages, 'none',
// 'transparent'; currentColor is black, the initial color). Opacity values are numbers in [0, 1]
// (clamped) or percentages. Anything else is "not valid": a renderer then uses the default.
#pragma once
#include <optional>
#include <string_view>

namespace shapevo::graph {

/// A length in user units, or nothing if `text` is not a length shapevo reads (em, ex, % too).
std::optional<double> parseLength(std::string_view text);

struct Paint {
    bool none = false;  ///< 'none' (or 'transparent'): nothing painted
    double r = 0, g = 0, b = 0;  ///< 0..1
};
/// A paint, or nothing if `text` is not one.
std::optional<Paint> parsePaint(std::string_view text);

/// An opacity clamped to [0, 1], or nothing if `text` is not a number or percentage.
std::optional<double> parseOpacity(std::string_view text);

}  // namespace shapevo::graph
