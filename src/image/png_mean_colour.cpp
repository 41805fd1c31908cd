// PNG mean colour: libpng's simplified API decodes to 8-bit RGBA, then sRGB -> linear and an
// alpha-weighted average (png_mean_colour.hpp).
#include "image/png_mean_colour.hpp"

#include <png.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "image/png_image.hpp"

namespace shapevo {

std::optional<std::array<float, 3>> pngMeanColour(std::span<const std::uint8_t> png) {
    if (png.empty()) return std::nullopt;
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) return std::nullopt;
    if (image.width == 0 || image.height == 0 || image.width > unsigned(kMaxPngSide) || image.height > unsigned(kMaxPngSide)) {
        png_image_free(&image);
        return std::nullopt;
    }
    image.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> rgba(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr)) {
        png_image_free(&image);
        return std::nullopt;
    }
    png_image_free(&image);
    std::array<double, 256> linear{};
    for (int i = 0; i < 256; ++i) {
        const double s = i / 255.0;
        linear[std::size_t(i)] = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    }
    double sum[3] = {0, 0, 0}, weight = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        const double a = rgba[i + 3] / 255.0;
        for (int ch = 0; ch < 3; ++ch) sum[ch] += a * linear[rgba[i + std::size_t(ch)]];
        weight += a;
    }
    if (weight <= 0) return std::nullopt;
    return std::array<float, 3>{float(sum[0] / weight), float(sum[1] / weight), float(sum[2] / weight)};
}

}  // namespace shapevo
