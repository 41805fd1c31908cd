// target.cover = "auto" (score/image/image_target.hpp): loadImageTarget reads a picture with a
// transparent pixel (alpha below the threshold) as the opaque preset does, and one without as the
// dark preset does, whatever the PNG's colour type carries the alpha (RGBA, grey + alpha, a
// palette with a tRNS chunk), and says which it chose (ImageTarget::autoCover).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../image/png_test_util.hpp"
#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "image/png_writer.hpp"
#include "score/image/image_target.hpp"

namespace shapevo {
namespace {

/// Whether pixel (x, y) of a 256 x 256 picture lies in its logo: a five-pointed star.
bool autoCoverInStar(int x, int y) {
    return std::hypot(x - 128, y - 128) < 60 + 40 * std::cos(5 * std::atan2(y - 128.0, x - 128.0));
}

/// A 256 x 256 palette PNG: entry 0 white, entry 1 black; `alpha` (tRNS, empty: none) per entry;
/// the star is entry `ink`, the rest entry 1 - ink.
void writeAutoCoverPalette(const std::string& path, int ink, std::vector<std::uint8_t> alpha) {
    test::writeTwoEntryPalettePng(path, ink, std::move(alpha), autoCoverInStar);
}

/// Hit and avoid pixels of `path` loaded at its own size under `rule`, and what auto chose.
struct AutoCoverLoad {
    std::uint64_t hit = 0, avoid = 0;
    TargetCover chose = TargetCover::Auto;
};
AutoCoverLoad autoCoverLoad(const std::string& path, const PixelRule& rule) {
    const ImageTarget t = loadImageTarget(path, rule, 256, 256, TargetFit::Contain);
    return {t.hitCount, t.avoidCount, t.autoCover};
}

std::uint64_t autoCoverStarPixels() {
    std::uint64_t n = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) n += autoCoverInStar(x, y);
    return n;
}

TEST(AutoCover, AWhiteLogoOnATransparentPaletteIsCoveredWhereOpaque) {
    test::TempDir dir;
    writeAutoCoverPalette(dir.file("logo.png"), 0, {255, 0});  // white star opaque, the rest clear (tRNS)
    const AutoCoverLoad a = autoCoverLoad(dir.file("logo.png"), PixelRule::forCover(TargetCover::Auto));
    EXPECT_EQ(a.chose, TargetCover::Opaque);
    EXPECT_EQ(a.hit, autoCoverStarPixels());
    EXPECT_EQ(a.avoid, 256u * 256u - autoCoverStarPixels());
    // the same as the opaque preset chosen by hand; the dark one finds nothing in it
    const AutoCoverLoad opaque = autoCoverLoad(dir.file("logo.png"), PixelRule::forCover(TargetCover::Opaque));
    EXPECT_EQ(opaque.hit, a.hit);
    EXPECT_EQ(opaque.chose, TargetCover::Auto);  // nothing was left to choose
    EXPECT_THROW(autoCoverLoad(dir.file("logo.png"), PixelRule::forCover(TargetCover::Dark)), InputError);
}

TEST(AutoCover, APictureWithoutTransparencyIsCoveredWhereDark) {
    test::TempDir dir;
    writeAutoCoverPalette(dir.file("black-on-white.png"), 1, {});  // no tRNS: opaque
    const AutoCoverLoad a = autoCoverLoad(dir.file("black-on-white.png"), PixelRule::forCover(TargetCover::Auto));
    EXPECT_EQ(a.chose, TargetCover::Dark);
    EXPECT_EQ(a.hit, autoCoverStarPixels());
    EXPECT_EQ(a.avoid, 256u * 256u - autoCoverStarPixels());
    // a tRNS chunk that makes every entry opaque is no transparency either
    writeAutoCoverPalette(dir.file("opaque-trns.png"), 1, {255, 255});
    EXPECT_EQ(autoCoverLoad(dir.file("opaque-trns.png"), PixelRule::forCover(TargetCover::Auto)).chose, TargetCover::Dark);
    // an RGBA picture whose alpha is 255 everywhere (the shipped city targets) reads as dark
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const std::uint8_t v = autoCoverInStar(x, y) ? 0 : 255;
            rgba.insert(rgba.end(), {v, v, v, 255});
        }
    writePngRgba(dir.file("rgba.png"), 256, 256, rgba);
    const AutoCoverLoad r = autoCoverLoad(dir.file("rgba.png"), PixelRule::forCover(TargetCover::Auto));
    EXPECT_EQ(r.chose, TargetCover::Dark);
    EXPECT_EQ(r.hit, autoCoverStarPixels());
}

TEST(AutoCover, RgbaAndGreyAlphaPicturesWithTransparencyAreCoveredWhereOpaque) {
    test::TempDir dir;
    std::vector<std::uint8_t> rgba;
    test::PngSpec grey;
    grey.width = grey.height = 256;
    grey.colourType = PNG_COLOR_TYPE_GRAY_ALPHA;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const bool in = autoCoverInStar(x, y);
            rgba.insert(rgba.end(), {200, 30, 30, std::uint8_t(in ? 255 : 0)});  // a red logo on transparency
            grey.bytes.insert(grey.bytes.end(), {255, std::uint8_t(in ? 255 : 0)});
        }
    writePngRgba(dir.file("rgba.png"), 256, 256, rgba);
    test::writeTestPng(dir.file("grey.png"), grey);
    for (const char* name : {"rgba.png", "grey.png"}) {
        const AutoCoverLoad a = autoCoverLoad(dir.file(name), PixelRule::forCover(TargetCover::Auto));
        EXPECT_EQ(a.chose, TargetCover::Opaque) << name;
        EXPECT_EQ(a.hit, autoCoverStarPixels()) << name;
    }
}

TEST(AutoCover, TransparentMeansBelowTheAlphaThreshold) {
    test::TempDir dir;
    // the star at alpha 255, the rest at alpha 200: nothing is transparent at the default threshold
    // (128), so the dark preset reads it (opaque would find no pixel to avoid); at threshold 201
    // the rest is transparent
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const bool in = autoCoverInStar(x, y);
            const std::uint8_t v = in ? 0 : 255;
            rgba.insert(rgba.end(), {v, v, v, std::uint8_t(in ? 255 : 200)});
        }
    writePngRgba(dir.file("veiled.png"), 256, 256, rgba);
    EXPECT_EQ(autoCoverLoad(dir.file("veiled.png"), PixelRule::forCover(TargetCover::Auto)).chose, TargetCover::Dark);
    const AutoCoverLoad high = autoCoverLoad(dir.file("veiled.png"), PixelRule::forCover(TargetCover::Auto, 201));
    EXPECT_EQ(high.chose, TargetCover::Opaque);
    EXPECT_EQ(high.hit, autoCoverStarPixels());
}

}  // namespace
}  // namespace shapevo
