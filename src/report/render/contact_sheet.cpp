// ContactSheet: a grid of three-quarter views with labels (contact_sheet.hpp).
#include "report/render/contact_sheet.hpp"

#include <cmath>
#include <stdexcept>

#include "base/input_error.hpp"
#include "image/png_writer.hpp"
#include "image/rgba_canvas.hpp"

namespace shapevo {

namespace {

constexpr Rgba kLabelColour{40, 42, 46, 255};

int columnsFor(int count) {
    int c = int(std::ceil(std::sqrt(double(count))));
    while (c > 1 && (c - 1) * (c - 1) >= count) --c;  // guard against sqrt rounding up
    while (c * c < count) ++c;
    return c;
}

}  // namespace

ContactSheet::ContactSheet(int count, PictureSize tile) : count_(count), tile_(tile) {
    if (count < 1) throw std::invalid_argument("ContactSheet: no tiles");
    columns_ = columnsFor(count);
    rows_ = (count + columns_ - 1) / columns_;
    const long long w = (long long)columns_ * (tile.width + kGutter) + kGutter;
    const long long h = (long long)rows_ * (tile.height + kGutter) + kGutter;
    if (w * h > kMaxPicturePixels || w > kMaxPictureSide * 4 || h > kMaxPictureSide * 4)
        throw InputError("--count", "", "a contact sheet of " + std::to_string(count) + " tiles of " + std::to_string(tile.width) +
                                            "x" + std::to_string(tile.height) + " would be " + std::to_string(w) + "x" +
                                            std::to_string(h) + " pixels, more than " + std::to_string(kMaxPicturePixels) +
                                            ": draw fewer models or choose a smaller --size");
    width_ = int(w);
    height_ = int(h);
    rgba_.resize(std::size_t(width_) * std::size_t(height_) * 4);
    for (std::size_t i = 0; i < rgba_.size(); i += 4)
        for (int ch = 0; ch < 4; ++ch) rgba_[i + std::size_t(ch)] = kGutterColour[std::size_t(ch)];
    // Undrawn tiles show the background: an empty mesh draws just that.
    for (int i = 0; i < count_; ++i) renderer_.render(Mesh{}, frameView(View::ThreeQuarter, {}, tile_.width, tile_.height), rgba_, width_, tileX(i), tileY(i));
}

int ContactSheet::tileX(int index) const { return kGutter + (index % columns_) * (tile_.width + kGutter); }
int ContactSheet::tileY(int index) const { return kGutter + (index / columns_) * (tile_.height + kGutter); }

void ContactSheet::draw(int index, const Mesh& mesh, const std::string& label) {
    if (index < 0 || index >= count_) throw std::invalid_argument("ContactSheet::draw: no such tile");
    const int x0 = tileX(index), y0 = tileY(index);
    renderer_.render(mesh, frameView(View::ThreeQuarter, boundingSphere(mesh), tile_.width, tile_.height), rgba_, width_, x0, y0);
    if (label.empty()) return;
    const int scale = tile_.height >= 160 ? 3 : tile_.height >= 64 ? 2 : 1, inset = 2 * scale;
    const int lw = RgbaCanvas::textWidth(label, scale), lh = RgbaCanvas::textHeight(scale);
    RgbaCanvas text(lw, lh, Rgba{0, 0, 0, 0});
    text.text(0, 0, label, kLabelColour, scale);
    for (int y = 0; y < lh; ++y)
        for (int x = 0; x < lw; ++x) {
            const int sx = x0 + inset + x, sy = y0 + tile_.height - inset - lh + y;
            if (sx < x0 || sx >= x0 + tile_.width || sy < y0 || sy >= y0 + tile_.height || text.at(x, y)[3] == 0) continue;
            std::uint8_t* p = rgba_.data() + (std::size_t(sy) * std::size_t(width_) + std::size_t(sx)) * 4;
            for (int ch = 0; ch < 4; ++ch) p[ch] = kLabelColour[std::size_t(ch)];
        }
}

void ContactSheet::write(const std::string& path) const { writePngRgba(path, width_, height_, rgba_); }

}  // namespace shapevo
