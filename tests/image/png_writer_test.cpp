// PNG writer: pixels survive a libpng round trip exactly; bad sizes and unwritable paths throw
// and leave no file behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/input_error.hpp"
#include "image/png_writer.hpp"
#include "png_read.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

TEST(PngWriter, RgbaPixelsRoundTripExactly) {
    test::TempDir dir;
    const int w = 37, h = 11;  // odd sizes: no row padding assumed
    std::vector<std::uint8_t> rgba(std::size_t(w * h * 4));
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t((i * 7919u) >> 3);
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;  // opaque: no alpha rounding in the reader
    const std::string path = dir.file("image.png");
    writePngRgba(path, w, h, rgba);
    bool ok = false;
    const test::RgbaImage back = test::readPngRgba(path, ok);
    ASSERT_TRUE(ok);
    EXPECT_EQ(back.width, w);
    EXPECT_EQ(back.height, h);
    EXPECT_EQ(back.rgba, rgba);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1) << "no temporary left";
}

TEST(PngWriter, BadSizeOrUnwritablePathThrowsAndLeavesNoFile) {
    test::TempDir dir;
    const std::uint8_t pixel[4] = {1, 2, 3, 255};
    EXPECT_THROW(writePngRgba(dir.file("zero.png"), 0, 1, pixel), InputError);
    EXPECT_THROW(writePngRgba(dir.file("negative.png"), 1, -1, pixel), InputError);
    EXPECT_THROW(writePngRgba(dir.file("missing/folder/a.png"), 1, 1, pixel), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace shapevo
