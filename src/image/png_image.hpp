// PNG files: read any PNG (grey, grey+alpha, palette with or without tRNS, RGB, RGBA; 1 to 16
// bits per sample; interlaced or not) into one luminance byte and one alpha byte per pixel, and
// write 8-bit RGBA images (for overlays and previews).
//
// Reading: samples of 16 bits are scaled to 8 (v * 255 / 65535, rounded); palette entries and
// grey values below 8 bits are expanded; tRNS becomes alpha; images without alpha get 255.
// Luminance = (299 R + 587 G + 114 B + 500) / 1000 in integers (Rec. 601), so a grey pixel keeps
// its value. Colour values are used as stored: gAMA, iCCP and sRGB chunks are ignored.
// Size limits: images wider or taller than kMaxPngSide pixels, or with more than kMaxPngPixels
// pixels in all, are refused from the IHDR chunk at the file's start, before anything is decoded
// or allocated. Non-interlaced images are decoded one row at a time (peak memory: the two output
// bytes per pixel and one row); interlaced ones need a full RGBA buffer (4 bytes per pixel more).
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace shapevo {

inline constexpr int kMaxPngSide = 16384;
inline constexpr long long kMaxPngPixels = 64LL * 1024 * 1024;  ///< 64 Mpixel (8192 x 8192)

struct PngImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> luminance;  ///< width * height, row 0 = the top row of the picture
    std::vector<std::uint8_t> alpha;      ///< width * height, 255 = opaque
};

/// Read a PNG. Throws InputError naming the file if it is missing, not a PNG, truncated,
/// corrupt, without pixels, larger than kMaxPngSide on a side or than kMaxPngPixels in all (the
/// message names the size and the limits).
PngImage readPng(const std::string& path);


}  // namespace shapevo
