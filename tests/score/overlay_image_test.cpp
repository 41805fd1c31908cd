// Overlay image: every pixel gets the colour of its outcome (hit, missed, extra, avoid, empty),
// rows keep their order, and the outcome colours are clearly different from each other.
#include <gtest/gtest.h>

#include <cstdlib>

#include "score/image/overlay_image.hpp"
#include "../image/png_read.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace overlay_image_test {  // named: a unity batch may hold another pixel()

Rgba pixel(const test::RgbaImage& img, int x, int y) {
    return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2), img.at(x, y, 3)};
}

TEST(OverlayImage, EachPixelShowsItsOutcomeColourInPlace) {
    test::TempDir dir;
    // 3 x 2: columns are target don't care / hit / avoid; the top row has the model, the bottom not.
    const int w = 3, h = 2;
    const std::uint8_t target[] = {kTargetDontCare, kTargetHit, kTargetAvoid, kTargetDontCare, kTargetHit, kTargetAvoid};
    const std::uint8_t model[] = {1, 1, 1, 0, 0, 0};
    const std::string path = dir.file("overlay.png");
    writeOverlayPng(path, w, h, target, model);
    bool ok = false;
    const test::RgbaImage img = test::readPngRgba(path, ok);
    ASSERT_TRUE(ok);
    ASSERT_EQ(img.width, w);
    ASSERT_EQ(img.height, h);
    EXPECT_EQ(pixel(img, 0, 0), kOverlayExtra);
    EXPECT_EQ(pixel(img, 1, 0), kOverlayHit);
    EXPECT_EQ(pixel(img, 2, 0), kOverlayExtra);  // covering an avoid pixel is extra too
    EXPECT_EQ(pixel(img, 0, 1), kOverlayBackground);
    EXPECT_EQ(pixel(img, 1, 1), kOverlayMissed);
    EXPECT_EQ(pixel(img, 2, 1), kOverlayAvoid);
}

TEST(OverlayImage, NonZeroModelBytesCountAsCoveredAndUnknownTargetValuesAsDontCare) {
    EXPECT_EQ(overlayColour(kTargetHit, true), kOverlayHit);
    EXPECT_EQ(overlayColour(7, true), kOverlayExtra);
    EXPECT_EQ(overlayColour(7, false), kOverlayBackground);
    test::TempDir dir;
    const std::uint8_t target[] = {kTargetHit};
    const std::uint8_t model[] = {255};
    writeOverlayPng(dir.file("o.png"), 1, 1, target, model);
    bool ok = false;
    const test::RgbaImage img = test::readPngRgba(dir.file("o.png"), ok);
    ASSERT_TRUE(ok);
    EXPECT_EQ(pixel(img, 0, 0), kOverlayHit);
}

TEST(OverlayImage, OutcomeColoursAreClearlyDifferent) {
    const Rgba colours[] = {kOverlayHit, kOverlayMissed, kOverlayExtra, kOverlayAvoid, kOverlayBackground};
    for (std::size_t i = 0; i < 5; ++i)
        for (std::size_t j = i + 1; j < 5; ++j) {
            int distance = 0;
            for (int c = 0; c < 3; ++c) distance += std::abs(int(colours[i][c]) - int(colours[j][c]));
            EXPECT_GE(distance, 100) << "colours " << i << " and " << j;
        }
}

}  // namespace overlay_image_test
}  // namespace shapevo
