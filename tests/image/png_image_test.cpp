// PNG reading: every colour type and bit depth (written here with libpng directly), interlaced
// files, the writer's round trip, and every kind of bad file as an InputError naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "image/png_image.hpp"
#include "image/png_writer.hpp"
#include "png_test_util.hpp"

namespace shapevo {
namespace {

int lum(int r, int g, int b) { return (299 * r + 587 * g + 114 * b + 500) / 1000; }

/// A w x h picture of 16-bit RGBA samples with distinct, deterministic values.
struct Picture {
    int w, h;
    std::vector<int> r, g, b, a;  // 0..65535
    Picture(int w_, int h_) : w(w_), h(h_) {
        for (long long i = 0; i < w * h; ++i) {
            r.push_back(int((i * 7919) % 256 * 257));
            g.push_back(int((i * 104729 + 31) % 256 * 257));
            b.push_back(int((i * 1299709 + 97) % 256 * 257));
            a.push_back(int((i * 15485863 + 5) % 256 * 257));
        }
    }
};

void put16(std::vector<std::uint8_t>& out, int v) {
    out.push_back(std::uint8_t(v >> 8));
    out.push_back(std::uint8_t(v & 0xff));
}

/// Pack a picture into the samples of one colour type / depth (grey uses the red channel).
test::PngSpec pack(const Picture& p, int colourType, int depth, bool interlaced = false) {
    test::PngSpec s;
    s.width = p.w;
    s.height = p.h;
    s.bitDepth = depth;
    s.colourType = colourType;
    s.interlaced = interlaced;
    for (int y = 0; y < p.h; ++y) {
        int bits = 0, acc = 0;
        for (int x = 0; x < p.w; ++x) {
            const int i = y * p.w + x;
            auto sample = [&](int v16) {
                if (depth == 16) put16(s.bytes, v16);
                else if (depth == 8) s.bytes.push_back(std::uint8_t(v16 >> 8));
                else {  // sub-byte grey: the top `depth` bits
                    acc = (acc << depth) | (v16 >> (16 - depth));
                    bits += depth;
                    if (bits == 8) s.bytes.push_back(std::uint8_t(acc)), bits = 0, acc = 0;
                }
            };
            switch (colourType) {
            case PNG_COLOR_TYPE_GRAY: sample(p.r[i]); break;
            case PNG_COLOR_TYPE_GRAY_ALPHA: sample(p.r[i]), sample(p.a[i]); break;
            case PNG_COLOR_TYPE_RGB: sample(p.r[i]), sample(p.g[i]), sample(p.b[i]); break;
            case PNG_COLOR_TYPE_RGB_ALPHA: sample(p.r[i]), sample(p.g[i]), sample(p.b[i]), sample(p.a[i]); break;
            }
        }
        if (bits) s.bytes.push_back(std::uint8_t(acc << (8 - bits)));
    }
    return s;
}

class PngRead : public ::testing::Test {
protected:
    test::TempDir dir;
};

TEST_F(PngRead, EightAndSixteenBitGreyRgbAndAlphaGiveLuminanceAndAlpha) {
    const Picture p(13, 7);
    struct Case {
        int type, depth;
    };
    for (const Case c : {Case{PNG_COLOR_TYPE_GRAY, 8}, Case{PNG_COLOR_TYPE_GRAY, 16}, Case{PNG_COLOR_TYPE_GRAY_ALPHA, 8},
                         Case{PNG_COLOR_TYPE_GRAY_ALPHA, 16}, Case{PNG_COLOR_TYPE_RGB, 8}, Case{PNG_COLOR_TYPE_RGB, 16},
                         Case{PNG_COLOR_TYPE_RGB_ALPHA, 8}, Case{PNG_COLOR_TYPE_RGB_ALPHA, 16}}) {
        SCOPED_TRACE("colour type " + std::to_string(c.type) + ", " + std::to_string(c.depth) + " bits");
        const std::string path = dir.file("t.png");
        test::writeTestPng(path, pack(p, c.type, c.depth));
        const PngImage im = readPng(path);
        ASSERT_EQ(im.width, 13);
        ASSERT_EQ(im.height, 7);
        const bool grey = !(c.type & PNG_COLOR_MASK_COLOR), alpha = c.type & PNG_COLOR_MASK_ALPHA;
        for (int i = 0; i < p.w * p.h; ++i) {
            const int r = p.r[i] / 257, g = p.g[i] / 257, b = p.b[i] / 257;
            EXPECT_EQ(im.luminance[i], grey ? r : lum(r, g, b)) << "pixel " << i;
            EXPECT_EQ(im.alpha[i], alpha ? p.a[i] / 257 : 255) << "pixel " << i;
        }
    }
}

TEST_F(PngRead, SixteenBitSamplesAreRoundedNotTruncated) {
    test::PngSpec s;
    s.width = 3;
    s.height = 1;
    s.bitDepth = 16;
    for (int v : {0x01c0, 0xff00, 0x8080}) put16(s.bytes, v);  // 1.74 -> 2, 254.0 -> 254, 128.0 -> 128
    test::writeTestPng(dir.file("t.png"), s);
    const PngImage im = readPng(dir.file("t.png"));
    EXPECT_EQ(im.luminance[0], 2);    // the high byte would be 1
    EXPECT_EQ(im.luminance[1], 254);  // the high byte would be 255
    EXPECT_EQ(im.luminance[2], 128);
}

TEST_F(PngRead, SubByteGreyIsExpandedToTheFullRange) {
    const Picture p(9, 4);
    for (int depth : {1, 2, 4}) {
        SCOPED_TRACE(std::to_string(depth) + " bits");
        test::writeTestPng(dir.file("t.png"), pack(p, PNG_COLOR_TYPE_GRAY, depth));
        const PngImage im = readPng(dir.file("t.png"));
        const int top = (1 << depth) - 1;
        for (int i = 0; i < p.w * p.h; ++i) EXPECT_EQ(im.luminance[i], (p.r[i] >> (16 - depth)) * 255 / top) << i;
    }
}

TEST_F(PngRead, PalettesWithAndWithoutTransparency) {
    test::PngSpec s;
    s.width = 4;
    s.height = 2;
    s.colourType = PNG_COLOR_TYPE_PALETTE;
    s.palette = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {40, 80, 120}};
    s.bytes = {0, 1, 2, 3, 3, 2, 1, 0};
    test::writeTestPng(dir.file("p.png"), s);
    PngImage im = readPng(dir.file("p.png"));
    const int expected[4] = {lum(255, 0, 0), lum(0, 255, 0), lum(0, 0, 255), lum(40, 80, 120)};
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(im.luminance[i], expected[s.bytes[i]]);
        EXPECT_EQ(im.alpha[i], 255);
    }
    s.paletteAlpha = {0, 100};  // entries 2 and 3 stay opaque
    test::writeTestPng(dir.file("t.png"), s);
    im = readPng(dir.file("t.png"));
    const int alpha[4] = {0, 100, 255, 255};
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(im.luminance[i], expected[s.bytes[i]]);
        EXPECT_EQ(im.alpha[i], alpha[s.bytes[i]]);
    }
    s.bitDepth = 2;  // four entries fit two bits: pack 4 pixels per byte
    s.bytes = {0b00011011, 0b11100100};
    test::writeTestPng(dir.file("t2.png"), s);
    im = readPng(dir.file("t2.png"));
    const int index[8] = {0, 1, 2, 3, 3, 2, 1, 0};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(im.alpha[i], alpha[index[i]]);
}

TEST_F(PngRead, InterlacedFilesGiveTheSamePixels) {
    const Picture p(19, 11);  // not a multiple of 8: every Adam7 pass is partial
    for (int type : {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_RGB_ALPHA}) {
        test::writeTestPng(dir.file("plain.png"), pack(p, type, 8, false));
        test::writeTestPng(dir.file("adam7.png"), pack(p, type, 8, true));
        const PngImage a = readPng(dir.file("plain.png")), b = readPng(dir.file("adam7.png"));
        EXPECT_EQ(a.luminance, b.luminance);
        EXPECT_EQ(a.alpha, b.alpha);
    }
}

TEST_F(PngRead, WriterRoundTripsRgbaThroughATemporaryFile) {
    const int w = 37, h = 5;
    std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 37 + 11);
    const std::string path = dir.file("out.png");
    writePngRgba(path, w, h, rgba);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const PngImage im = readPng(path);
    ASSERT_EQ(im.width, w);
    ASSERT_EQ(im.height, h);
    for (int i = 0; i < w * h; ++i) {
        EXPECT_EQ(im.luminance[i], lum(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]));
        EXPECT_EQ(im.alpha[i], rgba[4 * i + 3]);
    }
    EXPECT_THROW(writePngRgba(path, w, h + 1, rgba), std::invalid_argument);
    EXPECT_THROW(writePngRgba(dir.file("no/such/folder/x.png"), w, h, rgba), InputError);
}

/// readPng(path) must throw an InputError naming the file whose message contains `words`.
void expectBadPng(const std::string& path, const std::string& words) {
    try {
        readPng(path);
        ADD_FAILURE() << path << " was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST_F(PngRead, MissingEmptyAndForeignFilesAreInputErrors) {
    expectBadPng(dir.file("missing.png"), "no such file");
    expectBadPng(dir.path().string(), "not a regular file");
    test::writeFile(dir.file("empty.png"), "");
    expectBadPng(dir.file("empty.png"), "empty");
    test::writeFile(dir.file("text.png"), "P1\n2 2\n0 1 1 0\n");
    expectBadPng(dir.file("text.png"), "not a PNG");
    test::writeFile(dir.file("short.png"), "\x89PNG");
    expectBadPng(dir.file("short.png"), "not a PNG");
}

TEST_F(PngRead, TruncatedAndCorruptFilesAreInputErrors) {
    const Picture p(40, 30);
    test::writeTestPng(dir.file("good.png"), pack(p, PNG_COLOR_TYPE_RGB, 8));
    const std::string good = test::readFile(dir.file("good.png"));
    ASSERT_NO_THROW(readPng(dir.file("good.png")));
    for (std::size_t keep : {std::size_t(20), good.size() / 2, good.size() - 12}) {  // in IHDR, in IDAT, without IEND
        test::writeFile(dir.file("cut.png"), good.substr(0, keep));
        expectBadPng(dir.file("cut.png"), "truncated");
    }
    std::string bad = good;
    const std::size_t idat = bad.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    bad[idat + 10] = char(bad[idat + 10] ^ 0x55);  // data no longer matches the chunk's CRC
    test::writeFile(dir.file("crc.png"), bad);
    expectBadPng(dir.file("crc.png"), "unreadable PNG");
}

TEST_F(PngRead, ImagesWithoutPixelsOrTooLargeAreRefused) {
    test::writeFile(dir.file("zero.png"), test::pngHeaderOnly(0, 10));
    expectBadPng(dir.file("zero.png"), "zero");
    test::writeFile(dir.file("zeroh.png"), test::pngHeaderOnly(10, 0));
    expectBadPng(dir.file("zeroh.png"), "zero");
    test::writeFile(dir.file("huge.png"), test::pngHeaderOnly(kMaxPngSide + 1, 10));
    expectBadPng(dir.file("huge.png"), "limit");
    test::writeFile(dir.file("headonly.png"), test::pngHeaderOnly(10, 10));  // no IDAT, no IEND
    expectBadPng(dir.file("headonly.png"), "truncated");
}

TEST_F(PngRead, A30000By30000ImageIsRefusedFromItsHeaderNamingTheLimits) {
    // A valid 30000 x 1 file whose IHDR (CRC fixed) says 30000 x 30000: 2.7 GB of RGBA if decoded.
    test::writeFile(dir.file("huge.png"), test::forgedHugePng(dir.file("scratch.png"), 30000, 30000));
    expectBadPng(dir.file("huge.png"), "30000 x 30000 pixels, over the size limit of 16384 pixels on a side and 67108864");
    // within the side limit but over the pixel count: 16384 x 4097 > 64 Mpixel
    test::writeFile(dir.file("many.png"), test::pngHeaderOnly(kMaxPngSide, 4097));
    expectBadPng(dir.file("many.png"), "16384 x 4097 pixels, over the size limit");
    // exactly 64 Mpixel is within the limits: refused only for what it lacks (here, its data)
    test::writeFile(dir.file("limit.png"), test::pngHeaderOnly(8192, 8192));
    expectBadPng(dir.file("limit.png"), "truncated");
}

TEST(PngReadRegression, AHugeAncillaryChunkIsSkippedNotAllocated) {  // found by fuzz_png_reader
    // 45 bytes announcing a 2 GB iTXt chunk: libpng used to allocate and zero 2 GB for it.
    expectBadPng(test::sourcePath("tests/fuzz/regressions/fuzz_png_reader/itxt_length_2gb.png"), "truncated");
}

}  // namespace
}  // namespace shapevo
