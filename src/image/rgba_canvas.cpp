// RgbaCanvas: straight alpha blending, DDA lines, and a 3 x 5 bitmap font for numbers.
#include "image/rgba_canvas.hpp"

#include <algorithm>
#include <cmath>

namespace shapevo {

namespace {
/// 3 x 5 glyphs, rows top to bottom, 3 bits per row (bit 2 = left column).
int glyph(char ch) {
    switch (ch) {
    case '0': return 0b111'101'101'101'111;
    case '1': return 0b010'110'010'010'111;
    case '2': return 0b111'001'111'100'111;
    case '3': return 0b111'001'111'001'111;
    case '4': return 0b101'101'111'001'001;
    case '5': return 0b111'100'111'001'111;
    case '6': return 0b111'100'111'101'111;
    case '7': return 0b111'001'001'001'001;
    case '8': return 0b111'101'111'101'111;
    case '9': return 0b111'101'111'001'111;
    case '.': return 0b000'000'000'000'010;
    case '-': return 0b000'000'111'000'000;
    case '+': return 0b000'010'111'010'000;
    case 'e': return 0b000'011'111'100'011;
    default: return 0;
    }
}
constexpr int kAdvance = 4;  // glyph width 3 plus one column of space
}  // namespace

RgbaCanvas::RgbaCanvas(int width, int height, Rgba background)
    : width_(width), height_(height), rgba_(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)) * 4) {
    for (std::size_t i = 0; i < rgba_.size(); i += 4)
        for (std::size_t k = 0; k < 4; ++k) rgba_[i + k] = background[k];
}

Rgba RgbaCanvas::at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 4;
    return {rgba_[i], rgba_[i + 1], rgba_[i + 2], rgba_[i + 3]};
}

void RgbaCanvas::blend(int x, int y, Rgba c) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    std::uint8_t* p = &rgba_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 4];
    const int a = c[3];
    for (int k = 0; k < 3; ++k) p[k] = std::uint8_t((c[std::size_t(k)] * a + p[k] * (255 - a) + 127) / 255);
    p[3] = std::uint8_t(a + (p[3] * (255 - a) + 127) / 255);
}

void RgbaCanvas::line(double x0, double y0, double x1, double y1, Rgba c, int thickness) {
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return;
    const double lim = 4.0 * (width_ + height_);  // a wild point cannot make the loop endless
    x0 = std::clamp(x0, -lim, lim), x1 = std::clamp(x1, -lim, lim);
    y0 = std::clamp(y0, -lim, lim), y1 = std::clamp(y1, -lim, lim);
    const int steps = std::max(1, int(std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0)))));
    const int before = (thickness - 1) / 2;
    for (int i = 0; i <= steps; ++i) {
        const double t = double(i) / steps;
        const int x = int(std::lround(x0 + (x1 - x0) * t)), y = int(std::lround(y0 + (y1 - y0) * t));
        rect(x - before, y - before, x - before + thickness - 1, y - before + thickness - 1, c);
    }
}

void RgbaCanvas::span(int x, int y0, int y1, Rgba c) {
    if (y0 > y1) std::swap(y0, y1);
    for (int y = std::max(y0, 0); y <= std::min(y1, height_ - 1); ++y) blend(x, y, c);
}

void RgbaCanvas::rect(int x0, int y0, int x1, int y1, Rgba c) {
    for (int x = std::max(std::min(x0, x1), 0); x <= std::min(std::max(x0, x1), width_ - 1); ++x) span(x, y0, y1, c);
}

int RgbaCanvas::text(int x, int y, const std::string& s, Rgba c, int scale) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        const int bits = glyph(s[i]);
        for (int row = 0; row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if (bits >> ((4 - row) * 3 + (2 - col)) & 1)
                    rect(x + (int(i) * kAdvance + col) * scale, y + row * scale,
                         x + (int(i) * kAdvance + col) * scale + scale - 1, y + row * scale + scale - 1, c);
    }
    return textWidth(s, scale);
}

int RgbaCanvas::textWidth(const std::string& s, int scale) {
    return s.empty() ? 0 : (int(s.size()) * kAdvance - 1) * scale;
}

}  // namespace shapevo

