// pngMeanColour: the alpha-weighted mean of a PNG's pixels in linear RGB, and nothing for bytes
// that are not a PNG or an image without any opaque pixel.
#include <gtest/gtest.h>

#include <vector>

#include "image/png_mean_colour.hpp"
#include "image/png_writer.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

std::vector<std::uint8_t> pngOf(int w, int h, const std::vector<std::uint8_t>& rgba) {
    test::TempDir dir;
    writePngRgba(dir.file("p.png"), w, h, rgba);
    const std::string bytes = test::readFile(dir.file("p.png"));
    return {bytes.begin(), bytes.end()};
}

TEST(PngMeanColour, AveragesInLinearLightWeightedByAlpha) {
    const auto mean = pngMeanColour(pngOf(3, 1, {255, 0, 0, 255, 0, 0, 255, 255, 0, 255, 0, 0}));
    ASSERT_TRUE(mean.has_value());
    EXPECT_FLOAT_EQ((*mean)[0], 0.5f);
    EXPECT_FLOAT_EQ((*mean)[1], 0.0f) << "the transparent green pixel does not count";
    EXPECT_FLOAT_EQ((*mean)[2], 0.5f);
    const auto grey = pngMeanColour(pngOf(1, 1, {188, 188, 188, 255}));
    ASSERT_TRUE(grey.has_value());
    EXPECT_NEAR((*grey)[0], 0.5029f, 1e-3) << "sRGB 188 is linear 0.503";
}

TEST(PngMeanColour, NothingForBytesThatAreNotAPngOrAnInvisibleImage) {
    EXPECT_FALSE(pngMeanColour({}).has_value());
    const std::vector<std::uint8_t> text{'h', 'e', 'l', 'l', 'o'};
    EXPECT_FALSE(pngMeanColour(text).has_value());
    EXPECT_FALSE(pngMeanColour(pngOf(2, 1, {9, 9, 9, 0, 9, 9, 9, 0})).has_value());
    auto cut = pngOf(4, 4, std::vector<std::uint8_t>(64, 200));
    cut.resize(cut.size() / 2);
    EXPECT_FALSE(pngMeanColour(cut).has_value());
}

}  // namespace
}  // namespace shapevo
