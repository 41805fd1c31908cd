// PNG writer: an 8-bit RGBA image to a PNG file (libpng), written atomically.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace shapevo {

/// Writes `width` x `height` pixels of `rgba` (4 bytes per pixel, rows top to bottom, no padding)
/// to `path` as an 8-bit RGBA PNG; the file appears atomically (temporary file, then rename).
/// @throw InputError naming `path` if the size is not positive or the file cannot be written;
///        std::invalid_argument if `rgba` does not hold width * height * 4 bytes.
void writePngRgba(const std::string& path, int width, int height, std::span<const std::uint8_t> rgba);

}  // namespace shapevo
