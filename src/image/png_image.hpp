// PNG files: read any PNG (grey, grey+alpha, palette with or without tRNS, RGB, RGBA; 1 to 16
// bits per sample; interlaced or not) into one luminance byte and one alpha byte per pixel, and
// write 8-bit RGBA images (for overlays and previews).
//
// Reading: samples of 16 bits are scaled to 8 (v * 255 / 65535, rounded); palette entries and
// grey values below 8 bits are expanded; tRNS becomes alpha; images without alpha get 255.
// Luminance = (299 R + 587 G + 114 B + 500) / 1000 in integers (Rec. 601), so a grey pixel keeps
// its value. Colour values are used as stored: gAMA, iCCP and sRGB chunks are ignored.
// Images wider or taller than kMaxPngSide pixels are refused before anything is allocated.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace shapevo {

inline constexpr int kMaxPngSide = 16384;

struct PngImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> luminance;  ///< width * height, row 0 = the top row of the picture
    std::vector<std::uint8_t> alpha;      ///< width * height, 255 = opaque
};

/// Read a PNG. Throws InputError naming the file if it is missing, not a PNG, truncated,
/// corrupt, without pixels or larger than kMaxPngSide on a side.
PngImage readPng(const std::string& path);


}  // namespace shapevo
