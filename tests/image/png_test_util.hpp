// Test helper: write a PNG of any colour type, bit depth and interlacing with libpng directly
// (independent of image/png_image.cpp), and CRC-32 for hand-made chunks.
#pragma once
#include <png.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace shapevo::test {

struct PngSpec {
    int width = 0, height = 0;
    int bitDepth = 8;
    int colourType = PNG_COLOR_TYPE_GRAY;
    bool interlaced = false;
    std::vector<std::uint8_t> bytes;       ///< packed rows as libpng expects them (16-bit samples big-endian)
    std::vector<png_color> palette;        ///< PNG_COLOR_TYPE_PALETTE
    std::vector<std::uint8_t> paletteAlpha;  ///< tRNS for palettes
};

inline void writeTestPng(const std::string& path, const PngSpec& s) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(s.width), png_uint_32(s.height), s.bitDepth, s.colourType,
                 s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), int(s.palette.size()));
    if (!s.paletteAlpha.empty()) png_set_tRNS(png, info, s.paletteAlpha.data(), int(s.paletteAlpha.size()), nullptr);
    png_write_info(png, info);
    const std::size_t stride = s.bytes.size() / std::size_t(s.height);
    std::vector<png_bytep> rows;
    for (int y = 0; y < s.height; ++y) rows.push_back(const_cast<png_bytep>(s.bytes.data() + std::size_t(y) * stride));
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

/// A 256 x 256 palette PNG of two entries, 0 white and 1 black, with `alpha` per entry (a tRNS
/// chunk; empty: none): entry `ink` where `inside(x, y)`, entry 1 - ink elsewhere.
template <class Inside>
void writeTwoEntryPalettePng(const std::string& path, int ink, std::vector<std::uint8_t> alpha, Inside inside) {
    PngSpec s;
    s.width = s.height = 256;
    s.colourType = PNG_COLOR_TYPE_PALETTE;
    s.palette = {png_color{255, 255, 255}, png_color{0, 0, 0}};
    s.paletteAlpha = std::move(alpha);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) s.bytes.push_back(std::uint8_t(inside(x, y) ? ink : 1 - ink));
    writeTestPng(path, s);
}

inline std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

inline std::string bigEndian(std::uint32_t v) {
    return {char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
}

/// A PNG signature and an IHDR chunk (valid CRC) with the given size, and nothing else.
inline std::string pngHeaderOnly(std::uint32_t width, std::uint32_t height) {
    const std::string body = "IHDR" + bigEndian(width) + bigEndian(height) + std::string("\x08\x00\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + bigEndian(13) + body + bigEndian(crc32(body));
}

/// A complete, valid-looking PNG (IHDR, IDAT, IEND with good CRCs) that announces width x
/// height pixels but holds the data of a width x 1 grey image: what a huge image's header looks
/// like, for a few bytes. A reader must refuse it from the IHDR.
inline std::string forgedHugePng(const std::string& scratchPath, std::uint32_t width, std::uint32_t height) {
    PngSpec s;
    s.width = int(width), s.height = 1;
    s.bytes.assign(width, 0);
    writeTestPng(scratchPath, s);
    std::FILE* f = std::fopen(scratchPath.c_str(), "rb");
    std::string bytes;
    for (int c; (c = std::fgetc(f)) != EOF;) bytes.push_back(char(c));
    std::fclose(f);
    bytes.replace(20, 4, bigEndian(height));  // IHDR data starts at 16: width, then height
    bytes.replace(29, 4, bigEndian(crc32(bytes.substr(12, 17))));
    return bytes;
}

}  // namespace shapevo::test
