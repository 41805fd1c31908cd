// Test helper for the PNG writer tests: read a PNG back as 8-bit RGBA with libpng.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <png.h>

namespace shapevo::test {

struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  ///< rows top to bottom
    std::uint8_t at(int x, int y, int channel) const { return rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + std::size_t(channel)]; }
};

/// Reads `path`; `ok` is false (and the image empty) if libpng cannot read it.
inline RgbaImage readPngRgba(const std::string& path, bool& ok) {
    RgbaImage out;
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    ok = png_image_begin_read_from_file(&image, path.c_str()) != 0;
    if (!ok) return out;
    image.format = PNG_FORMAT_RGBA;
    out.width = int(image.width);
    out.height = int(image.height);
    out.rgba.resize(PNG_IMAGE_SIZE(image));
    ok = png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr) != 0;
    png_image_free(&image);
    if (!ok) out = RgbaImage{};
    return out;
}

}  // namespace shapevo::test
