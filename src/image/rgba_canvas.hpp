// RgbaCanvas: a small 8-bit RGBA raster for simple plots written as PNG: blended pixels, thick
// lines, vertical spans, rectangles and numbers in a built-in 3 x 5 pixel font (digits, '.',
// '-', '+', 'e'; enough for tick labels).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/rgba.hpp"

namespace shapevo {

class RgbaCanvas {
public:
    RgbaCanvas(int width, int height, Rgba background);

    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<std::uint8_t>& pixels() const { return rgba_; }  ///< rows top to bottom
    Rgba at(int x, int y) const;

    /// Blends `c` over pixel (x, y) with c's alpha; pixels off the canvas are ignored.
    void blend(int x, int y, Rgba c);
    /// A line between pixel centres, `thickness` pixels wide (square brush). Brush squares
    /// overlap, so use opaque colours for lines.
    void line(double x0, double y0, double x1, double y1, Rgba c, int thickness = 1);
    /// Pixels x, y0..y1 (inclusive, either order).
    void span(int x, int y0, int y1, Rgba c);
    void rect(int x0, int y0, int x1, int y1, Rgba c);
    /// Draws `text` with its top-left corner at (x, y), glyphs scaled by `scale`; characters the
    /// font lacks are left blank. Returns the width drawn.
    int text(int x, int y, const std::string& text, Rgba c, int scale = 1);
    static int textWidth(const std::string& text, int scale = 1);
    static int textHeight(int scale = 1) { return 5 * scale; }

private:
    int width_, height_;
    std::vector<std::uint8_t> rgba_;
};

}  // namespace shapevo
