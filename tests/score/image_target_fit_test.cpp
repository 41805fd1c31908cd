// Fitting a picture into the camera's frame (score/image/image_target.hpp): the placements of contain,
// cover, stretch and exact worked out by hand; the area-vote resampling against a brute-force
// reference on random pictures; exact pixel counts on tiny pictures; the cover presets; the hash
// telling fitted targets apart; and loadImageTarget's size checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "image/png_writer.hpp"
#include "score/image/image_target.hpp"

namespace shapevo {
namespace {

enum Class { kDontCare = 0, kHit = 1, kAvoid = 2 };

/// A picture of the given classes (row-major), built through the dark preset with alpha 0 for
/// don't care.
ImageTarget picture(int w, int h, const std::vector<int>& classes) {
    std::vector<std::uint8_t> lum(classes.size()), alpha(classes.size(), 255);
    for (std::size_t i = 0; i < classes.size(); ++i) {
        lum[i] = classes[i] == kHit ? 0 : 255;
        if (classes[i] == kDontCare) alpha[i] = 0;
    }
    return makeImageTarget(w, h, lum, alpha, PixelRule{});
}

int classOf(const ImageTarget& t, int x, int y) { return t.isHit(x, y) ? kHit : t.isAvoid(x, y) ? kAvoid : kDontCare; }

/// Brute force: place picture pixel (i, j) at the real rectangle the placement gives it in the
/// frame, intersect it with every frame pixel (all pictures pixels, no spans), vote by area.
/// Coordinates are scaled by the picture's size so that every edge is a whole number.
std::vector<int> referenceFit(const ImageTarget& pic, int fw, int fh, const TargetPlacement& p) {
    const long long W = pic.width, H = pic.height;
    std::vector<int> out(std::size_t(fw) * std::size_t(fh), kDontCare);
    for (int y = 0; y < fh; ++y)
        for (int x = 0; x < fw; ++x) {
            long long area[3] = {0, 0, 0};
            for (int j = 0; j < H; ++j)
                for (int i = 0; i < W; ++i) {
                    // frame x in units of 1 / W: picture pixel i spans [p.x W + i p.width, p.x W + (i + 1) p.width)
                    const long long ax = std::max<long long>(x * W, p.x * W + i * (long long)p.width);
                    const long long bx = std::min<long long>((x + 1) * W, p.x * W + (i + 1) * (long long)p.width);
                    const long long ay = std::max<long long>(y * H, p.y * H + j * (long long)p.height);
                    const long long by = std::min<long long>((y + 1) * H, p.y * H + (j + 1) * (long long)p.height);
                    if (bx > ax && by > ay) area[classOf(pic, i, j)] += (bx - ax) * (by - ay);
                }
            int c = kDontCare;
            if (area[kHit] > 0 && area[kHit] >= area[kAvoid] && area[kHit] >= area[kDontCare]) c = kHit;
            else if (area[kAvoid] > 0 && area[kAvoid] >= area[kDontCare]) c = kAvoid;
            out[std::size_t(y) * std::size_t(fw) + std::size_t(x)] = c;
        }
    return out;
}

TEST(TargetFit, PlacementsOfARealLogoInThePapersFrame) {
    // 229 x 304 into 800 x 600: contain fills the height (600 / 304 * 229 = 451.97 -> 452),
    // cover the width (800 / 229 * 304 = 1062.0 -> 1062, cut by 231 above and below).
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Contain), (TargetPlacement{174, 0, 452, 600}));
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Cover), (TargetPlacement{0, -231, 800, 1062}));
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Stretch), (TargetPlacement{0, 0, 800, 600}));
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Exact), (TargetPlacement{0, 0, 800, 600}));
    // 400 x 150 (wider than the frame): contain fills the width, cover the height.
    EXPECT_EQ(placeTarget(400, 150, 800, 600, TargetFit::Contain), (TargetPlacement{0, 150, 800, 300}));
    EXPECT_EQ(placeTarget(400, 150, 800, 600, TargetFit::Cover), (TargetPlacement{-400, 0, 1600, 600}));
    // The same aspect: the whole frame either way; a tiny sliver keeps at least one pixel.
    EXPECT_EQ(placeTarget(400, 300, 800, 600, TargetFit::Contain), (TargetPlacement{0, 0, 800, 600}));
    EXPECT_EQ(placeTarget(400, 300, 800, 600, TargetFit::Cover), (TargetPlacement{0, 0, 800, 600}));
    EXPECT_EQ(placeTarget(16384, 8, 800, 600, TargetFit::Contain), (TargetPlacement{0, 299, 800, 1}));
}

TEST(TargetFit, AreaVoteEqualsTheBruteForceReferenceOnRandomPictures) {
    std::mt19937 rng(14);
    const int frames[][2] = {{13, 11}, {3, 4}, {16, 6}, {7, 7}, {1, 5}};
    int checked = 0;
    for (int round = 0; round < 12; ++round) {
        const int w = 1 + int(rng() % 9), h = 1 + int(rng() % 9);
        std::vector<int> classes(std::size_t(w * h));
        for (int& c : classes) c = int(rng() % 3);
        const ImageTarget pic = picture(w, h, classes);
        for (const auto& f : frames)
            for (TargetFit fit : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch}) {
                const TargetPlacement p = placeTarget(w, h, f[0], f[1], fit);
                const ImageTarget t = fitImageTarget(pic, f[0], f[1], p);
                const std::vector<int> want = referenceFit(pic, f[0], f[1], p);
                ASSERT_EQ(t.width, f[0]);
                ASSERT_EQ(t.height, f[1]);
                std::uint64_t hits = 0, avoids = 0;
                for (int y = 0; y < f[1]; ++y)
                    for (int x = 0; x < f[0]; ++x) {
                        const int c = want[std::size_t(y) * std::size_t(f[0]) + std::size_t(x)];
                        ASSERT_EQ(classOf(t, x, y), c) << w << "x" << h << " into " << f[0] << "x" << f[1] << " "
                                                       << targetFitName(fit) << " at " << x << "," << y;
                        hits += c == kHit, avoids += c == kAvoid;
                    }
                EXPECT_EQ(t.hitCount, hits);
                EXPECT_EQ(t.avoidCount, avoids);
                ++checked;
            }
    }
    EXPECT_EQ(checked, 12 * 5 * 3);
}

TEST(TargetFit, ExactPixelCountsOnTinyPictures) {
    const ImageTarget halves = picture(2, 1, {kHit, kAvoid});  // left hit, right avoid
    // contain: an 8 x 4 band in rows 2..5, margins don't care
    ImageTarget t = fitImageTarget(halves, 8, 8, placeTarget(2, 1, 8, 8, TargetFit::Contain));
    EXPECT_EQ(t.hitCount, 16u);
    EXPECT_EQ(t.avoidCount, 16u);
    EXPECT_TRUE(t.isHit(0, 2) && t.isHit(3, 5) && t.isAvoid(4, 2) && !t.isHit(0, 1) && !t.isAvoid(7, 6));
    // cover: 16 x 8, cut to its middle 8 columns: half hit, half avoid, nothing don't care
    t = fitImageTarget(halves, 8, 8, placeTarget(2, 1, 8, 8, TargetFit::Cover));
    EXPECT_EQ(t.hitCount, 32u);
    EXPECT_EQ(t.avoidCount, 32u);
    // stretch: the same counts, over the whole frame
    t = fitImageTarget(halves, 8, 8, placeTarget(2, 1, 8, 8, TargetFit::Stretch));
    EXPECT_EQ(t.hitCount, 32u);
    EXPECT_EQ(t.avoidCount, 32u);
    // one frame pixel over both halves: a tie goes to hit
    t = fitImageTarget(halves, 1, 1, placeTarget(2, 1, 1, 1, TargetFit::Stretch));
    EXPECT_EQ(t.hitCount, 1u);
    // 3 x 1 into 2 x 1: pixel 0 holds all of picture pixel 0 and half of pixel 1
    t = fitImageTarget(picture(3, 1, {kAvoid, kHit, kHit}), 2, 1, {0, 0, 2, 1});
    EXPECT_TRUE(t.isAvoid(0, 0));  // avoid 2 of 3 units against hit 1
    EXPECT_TRUE(t.isHit(1, 0));
    // don't care wins a majority too: a mostly transparent block stays don't care
    t = fitImageTarget(picture(3, 1, {kDontCare, kDontCare, kHit}), 1, 1, {0, 0, 1, 1});
    EXPECT_EQ(t.hitCount + t.avoidCount, 0u);
}

TEST(TargetFit, APictureOfTheFramesSizeComesThroughUnchangedWhateverTheFit) {
    std::mt19937 rng(3);
    std::vector<int> classes(70 * 9);
    for (int& c : classes) c = int(rng() % 3);
    const ImageTarget pic = picture(70, 9, classes);
    for (TargetFit fit : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch, TargetFit::Exact}) {
        const ImageTarget t = fitImageTarget(pic, 70, 9, placeTarget(70, 9, 70, 9, fit));
        EXPECT_EQ(t.hit, pic.hit) << targetFitName(fit);
        EXPECT_EQ(t.avoid, pic.avoid) << targetFitName(fit);
        EXPECT_EQ(t.hash, pic.hash) << targetFitName(fit);  // so checkpoints of today's targets still resume
    }
    // and the general path agrees with the shortcut (an identity placement in a larger frame)
    const ImageTarget big = fitImageTarget(pic, 72, 9, {1, 0, 70, 9});
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 70; ++x) ASSERT_EQ(classOf(big, x + 1, y), classOf(pic, x, y));
}

TEST(TargetFit, TheHashTellsFitsOfAnOddSizedPictureApart) {
    std::vector<int> classes(10 * 20, kAvoid);
    for (int y = 5; y < 15; ++y)
        for (int x = 2; x < 8; ++x) classes[std::size_t(y * 10 + x)] = kHit;
    const ImageTarget pic = picture(10, 20, classes);
    std::vector<std::uint64_t> hashes;
    for (TargetFit fit : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch})
        hashes.push_back(fitImageTarget(pic, 40, 30, placeTarget(10, 20, 40, 30, fit)).hash);
    EXPECT_NE(hashes[0], hashes[1]);
    EXPECT_NE(hashes[0], hashes[2]);
    EXPECT_NE(hashes[1], hashes[2]);
    EXPECT_EQ(hashes[0], fitImageTarget(pic, 40, 30, placeTarget(10, 20, 40, 30, TargetFit::Contain)).hash);
}

TEST(TargetCoverPreset, DarkLightAndOpaqueClassifyColourAndAlpha) {
    // black opaque, white opaque, grey 127 / 128 opaque, black transparent, white transparent
    const std::vector<std::uint8_t> lum = {0, 255, 127, 128, 0, 255}, alpha = {255, 255, 255, 255, 0, 127};
    auto classes = [&](const PixelRule& r) {
        const ImageTarget t = makeImageTarget(6, 1, lum, alpha, r);
        std::vector<int> c;
        for (int x = 0; x < 6; ++x) c.push_back(classOf(t, x, 0));
        return c;
    };
    EXPECT_EQ(classes(PixelRule::forCover(TargetCover::Dark)), (std::vector<int>{kHit, kAvoid, kHit, kAvoid, kDontCare, kDontCare}));
    EXPECT_EQ(classes(PixelRule{}), classes(PixelRule::forCover(TargetCover::Dark)));
    EXPECT_EQ(classes(PixelRule::forCover(TargetCover::Light)), (std::vector<int>{kAvoid, kHit, kAvoid, kHit, kDontCare, kDontCare}));
    EXPECT_EQ(classes(PixelRule::forCover(TargetCover::Opaque)), (std::vector<int>{kHit, kHit, kHit, kHit, kAvoid, kAvoid}));
    // the threshold decides what is transparent: at 100 the last pixel (alpha 127) is opaque
    EXPECT_EQ(classes(PixelRule::forCover(TargetCover::Opaque, 100)), (std::vector<int>{kHit, kHit, kHit, kHit, kAvoid, kHit}));
    for (TargetCover c : {TargetCover::Dark, TargetCover::Light, TargetCover::Opaque})
        EXPECT_NO_THROW(PixelRule::forCover(c).check("x.toml", "target")) << targetCoverName(c);
}

std::string loadError(const std::string& path, const PixelRule& rule, int fw, int fh, TargetFit fit) {
    try {
        loadImageTarget(path, rule, fw, fh, fit);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        return e.what();
    }
    return "accepted";
}

void writeGrey(const std::string& path, int w, int h, std::uint8_t v, std::uint8_t a = 255) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < w * h; ++i) rgba.insert(rgba.end(), {v, v, v, a});
    writePngRgba(path, w, h, rgba);
}

TEST(TargetFit, LoadRefusesTinyPicturesAndOddSizesOnlyWhenExact) {
    test::TempDir dir;
    writeGrey(dir.file("one.png"), 1, 1, 0);
    EXPECT_NE(loadError(dir.file("one.png"), PixelRule{}, 800, 600, TargetFit::Contain).find("1 x 1 pixels, too small"), std::string::npos);
    writeGrey(dir.file("thin.png"), 300, kMinTargetSide - 1, 0);
    EXPECT_NE(loadError(dir.file("thin.png"), PixelRule{}, 800, 600, TargetFit::Stretch).find("at least 8 pixels"), std::string::npos);
    writeGrey(dir.file("eight.png"), kMinTargetSide, kMinTargetSide, 0);
    const ImageTarget t = loadImageTarget(dir.file("eight.png"), PixelRule{}, 800, 600, TargetFit::Contain);
    EXPECT_EQ(t.hitCount, 600u * 600u);  // a black square fills a 600 x 600 square in the middle
    EXPECT_EQ(t.placement, (TargetPlacement{100, 0, 600, 600}));
    EXPECT_EQ(t.pictureWidth, 8);
    const std::string odd = loadError(dir.file("eight.png"), PixelRule{}, 800, 600, TargetFit::Exact);
    EXPECT_NE(odd.find("odd-sized"), std::string::npos) << odd;
    EXPECT_NE(odd.find("8 x 8"), std::string::npos) << odd;
    EXPECT_NE(odd.find("800 x 600"), std::string::npos) << odd;
    EXPECT_EQ(loadImageTarget(dir.file("eight.png"), PixelRule{}, 8, 8, TargetFit::Exact).hitCount, 64u);
}

TEST(TargetCoverPreset, LoadExplainsAPictureThePresetFindsNothingIn) {
    test::TempDir dir;
    writeGrey(dir.file("white-on-clear.png"), 16, 16, 255, 0);
    std::vector<std::uint8_t> rgba;  // a white 8 x 8 square on a transparent 16 x 16 background
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool in = x >= 4 && x < 12 && y >= 4 && y < 12;
            rgba.insert(rgba.end(), {255, 255, 255, std::uint8_t(in ? 255 : 0)});
        }
    writePngRgba(dir.file("logo.png"), 16, 16, rgba);
    const std::string dark = loadError(dir.file("logo.png"), PixelRule{}, 32, 32, TargetFit::Contain);
    EXPECT_NE(dark.find("no hit pixel"), std::string::npos) << dark;
    EXPECT_NE(dark.find("\"opaque\""), std::string::npos) << dark;  // names the way out
    const ImageTarget t = loadImageTarget(dir.file("logo.png"), PixelRule::forCover(TargetCover::Opaque), 32, 32);
    EXPECT_EQ(t.hitCount, 16u * 16u);
    EXPECT_EQ(t.avoidCount, 32u * 32u - 16u * 16u);
    EXPECT_EQ(loadImageTarget(dir.file("logo.png"), PixelRule::forCover(TargetCover::Light), 32, 32).hitCount, 16u * 16u);
    writeGrey(dir.file("opaque.png"), 16, 16, 0);
    const std::string none = loadError(dir.file("opaque.png"), PixelRule::forCover(TargetCover::Opaque), 32, 32, TargetFit::Contain);
    EXPECT_NE(none.find("no transparent pixel"), std::string::npos) << none;
    const std::string clear = loadError(dir.file("white-on-clear.png"), PixelRule::forCover(TargetCover::Opaque), 32, 32, TargetFit::Contain);
    EXPECT_NE(clear.find("no pixel has alpha >= 128"), std::string::npos) << clear;
}

}  // namespace
}  // namespace shapevo

namespace shapevo {
namespace {

// target.scale: contain and stretch within a centred box of the frame; a picture of the frame's
// size, cover and exact are placed as without it.
TEST(TargetScale, ContainAndStretchUseACentredPartOfTheFrame) {
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Contain, 0.5), (TargetPlacement{287, 150, 226, 300}));
    EXPECT_EQ(placeTarget(400, 150, 800, 600, TargetFit::Stretch, 0.5), (TargetPlacement{200, 150, 400, 300}));
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Contain, 1.0), placeTarget(229, 304, 800, 600, TargetFit::Contain));
    EXPECT_EQ(placeTarget(800, 600, 800, 600, TargetFit::Contain, 0.5), (TargetPlacement{0, 0, 800, 600}));
    EXPECT_EQ(placeTarget(229, 304, 800, 600, TargetFit::Cover, 0.5), placeTarget(229, 304, 800, 600, TargetFit::Cover));
    EXPECT_EQ(placeTarget(20, 20, 10, 10, TargetFit::Contain, 0.01), (TargetPlacement{4, 4, 1, 1}));
}

}  // namespace
}  // namespace shapevo
