// Image targets: pixel classification (hit / avoid / don't care) into bit rows, the size and
// content checks of loadImageTarget, PixelRule checks, and the papers' reference targets.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../image/png_test_util.hpp"
#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "image/png_image.hpp"
#include "image/png_writer.hpp"
#include "score/image/image_target.hpp"

namespace shapevo {
namespace {

const std::string kReference = test::sourcePath("targets/shapegenetics/");

/// A 70 x 8 grey+alpha picture (two words per row) with luminance x * 3 + y and alpha 0 on column 5.
void writeRamp(const std::string& path) {
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 70; ++x) {
            const auto v = std::uint8_t(x * 3 + y);
            rgba.insert(rgba.end(), {v, v, v, std::uint8_t(x == 5 ? 0 : 255)});
        }
    writePngRgba(path, 70, 8, rgba);
}

TEST(ImageTarget, DefaultRuleMakesDarkPixelsHitLightOnesAvoidAndTransparentOnesDontCare) {
    test::TempDir dir;
    writeRamp(dir.file("ramp.png"));
    const ImageTarget t = loadImageTarget(dir.file("ramp.png"), PixelRule{}, 70, 8);
    ASSERT_EQ(t.wordsPerRow(), 2);
    std::uint64_t hits = 0, avoids = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 70; ++x) {
            const int v = x * 3 + y;
            const bool care = x != 5;
            EXPECT_EQ(t.isHit(x, y), care && v <= 127) << x << "," << y;
            EXPECT_EQ(t.isAvoid(x, y), care && v >= 128) << x << "," << y;
            hits += t.isHit(x, y);
            avoids += t.isAvoid(x, y);
        }
    EXPECT_EQ(t.hitCount, hits);
    EXPECT_EQ(t.avoidCount, avoids);
    // bits past the width stay clear
    for (int y = 0; y < 8; ++y) EXPECT_EQ(t.hit[std::size_t(y) * 2 + 1] >> 6, 0u);
}

TEST(ImageTarget, CustomRangesLeaveTheGapAsDontCare) {
    std::vector<std::uint8_t> lum = {0, 10, 11, 99, 100, 200, 201, 255}, alpha(8, 255);
    alpha[0] = 9;
    PixelRule rule;
    rule.hitMin = 0, rule.hitMax = 10, rule.avoidMin = 100, rule.avoidMax = 200, rule.alphaThreshold = 10;
    const ImageTarget t = makeImageTarget(8, 1, lum, alpha, rule);
    const bool hit[8] = {false, true, false, false, false, false, false, false};
    const bool avoid[8] = {false, false, false, false, true, true, false, false};
    for (int x = 0; x < 8; ++x) {
        EXPECT_EQ(t.isHit(x, 0), hit[x]) << x;
        EXPECT_EQ(t.isAvoid(x, 0), avoid[x]) << x;
    }
    rule.avoidMin = 1, rule.avoidMax = 0;  // an empty range: nothing to avoid
    EXPECT_EQ(makeImageTarget(8, 1, lum, alpha, rule).avoidCount, 0u);
}

TEST(ImageTarget, HashDependsOnThePixels) {
    std::vector<std::uint8_t> lum(16, 0), alpha(16, 255);
    const ImageTarget a = makeImageTarget(4, 4, lum, alpha, PixelRule{});
    lum[7] = 255;
    const ImageTarget b = makeImageTarget(4, 4, lum, alpha, PixelRule{});
    EXPECT_NE(a.hash, b.hash);
    EXPECT_NE(a.hash, makeImageTarget(8, 2, lum, alpha, PixelRule{}).hash);
}

TEST(ImageTarget, OddSizedImageWithExactFitIsAnErrorNamingBothSizes) {
    test::TempDir dir;
    writeRamp(dir.file("ramp.png"));
    try {
        loadImageTarget(dir.file("ramp.png"), PixelRule{}, 800, 600, TargetFit::Exact);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.file(), dir.file("ramp.png"));
        EXPECT_NE(what.find("odd-sized"), std::string::npos) << what;
        EXPECT_NE(what.find("70 x 8"), std::string::npos) << what;
        EXPECT_NE(what.find("800 x 600"), std::string::npos) << what;
    }
}

TEST(ImageTarget, TargetWithoutHitPixelsIsAnError) {
    test::TempDir dir;
    std::vector<std::uint8_t> white(8 * 8 * 4, 255);
    writePngRgba(dir.file("white.png"), 8, 8, white);
    EXPECT_THROW(loadImageTarget(dir.file("white.png"), PixelRule{}, 8, 8), InputError);
    std::vector<std::uint8_t> clear(8 * 8 * 4, 0);  // black but fully transparent
    writePngRgba(dir.file("clear.png"), 8, 8, clear);
    try {
        loadImageTarget(dir.file("clear.png"), PixelRule{}, 8, 8);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no hit pixel"), std::string::npos) << e.what();
    }
}

TEST(ImageTarget, UnreadableFilesKeepTheirPngError) {
    test::TempDir dir;
    test::writeFile(dir.file("bad.png"), "not a png at all");
    EXPECT_THROW(loadImageTarget(dir.file("bad.png"), PixelRule{}, 4, 4), InputError);
}

TEST(PixelRule, BoundsAndOverlapsAreErrorsNamingTheKey) {
    auto whereOf = [](const PixelRule& r) {
        try {
            r.check("run.toml", "target");
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), "run.toml");
            return e.where();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(whereOf(PixelRule{}), "accepted");
    PixelRule r;
    r.hitMax = 300;
    EXPECT_EQ(whereOf(r), "target.hit_max");
    r = PixelRule{};
    r.avoidMin = -1;
    EXPECT_EQ(whereOf(r), "target.avoid_min");
    r = PixelRule{};
    r.alphaThreshold = 257;
    EXPECT_EQ(whereOf(r), "target.alpha_threshold");
    r = PixelRule{};
    r.avoidMin = 127;  // overlaps the hit range 0..127
    EXPECT_EQ(whereOf(r), "target.avoid_min");
    r.avoidMin = 200, r.avoidMax = 100;  // empty avoid range: fine
    EXPECT_EQ(whereOf(r), "accepted");
}

TEST(ImageTarget, PapersReferenceTargetsHaveTheirDocumentedBlackPixels) {
    // reference-targets/README.md: mickey has 23,473 black pixels, sketch1 42,320.
    PixelRule black;
    black.hitMax = 0, black.avoidMin = 1;
    EXPECT_EQ(loadImageTarget(kReference + "tree_target_mickey.png", black, 800, 600).hitCount, 23473u);
    EXPECT_EQ(loadImageTarget(kReference + "tree_target_sketch1.png", black, 800, 600).hitCount, 42320u);
    // With the default rule (luminance <= 127; counted with a separate decoder) and every pixel opaque.
    const ImageTarget m = loadImageTarget(kReference + "tree_target_mickey.png", PixelRule{}, 800, 600);
    EXPECT_EQ(m.hitCount, 23652u);
    EXPECT_EQ(m.hitCount + m.avoidCount, 800u * 600u);
    EXPECT_EQ(loadImageTarget(kReference + "tree_target_sketch1.png", PixelRule{}, 800, 600).hitCount, 44615u);
    EXPECT_EQ(loadImageTarget(kReference + "city_target_whale.png", PixelRule{}, 800, 600).hitCount, 202104u);
    EXPECT_EQ(loadImageTarget(kReference + "shoe_target.png", PixelRule{}, 800, 600).hitCount, 184146u);
}

}  // namespace
}  // namespace shapevo
