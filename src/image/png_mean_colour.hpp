// PNG mean colour: the average colour of a PNG image held in memory, in linear RGB, weighted by
// alpha (for drawing a textured material in one colour: report/render/mesh_renderer.hpp).
// libpng's simplified API decodes the image to 8-bit sRGB RGBA (any PNG colour type and depth).
// Images wider or taller than kMaxPngSide (png_image.hpp) are not decoded.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace shapevo {

/// The alpha-weighted mean of `png`'s pixels converted from sRGB to linear RGB, each channel in
/// [0, 1]; nullopt if the bytes are not a readable PNG, it is too large, or fully transparent.
std::optional<std::array<float, 3>> pngMeanColour(std::span<const std::uint8_t> png);

}  // namespace shapevo
