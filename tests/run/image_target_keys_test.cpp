// The [target] keys of an image target that fit it into the camera's frame and choose its pixels:
// target.fit (contain by default, cover, stretch, exact) and target.cover (auto by default, dark,
// light, opaque), their errors with place, cover against the explicit luminance ranges, and a
// relative target.image given with --set being taken from the current directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "run/config_file.hpp"
#include "score/image/image_kind.hpp"

namespace shapevo {
namespace {

const std::string kImage = "[grammar]\nfile = \"g.grammar\"\n[target]\nimage = \"logo.png\"\n";

RunSettings parse(const std::string& extra, const std::vector<std::string>& overrides = {}) {
    return parseConfig(kImage + extra, "/configs/x.toml", overrides);
}

InputError imageKeyError(const std::string& extra, const std::vector<std::string>& overrides = {}) {
    try {
        parse(extra, overrides);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted:\n" << extra;
    return InputError("", "", "");
}

/// The image kind's settings of a config that names an image target.
const ImageTargetSettings& imageOf(const RunSettings& s) {
    EXPECT_EQ(&s.target->kind(), &imageTargetKind);
    return static_cast<const ImageTargetSettings&>(*s.target);
}

void expectRule(const PixelRule& r, const PixelRule& want) {
    EXPECT_EQ(r.hitMin, want.hitMin);
    EXPECT_EQ(r.hitMax, want.hitMax);
    EXPECT_EQ(r.avoidMin, want.avoidMin);
    EXPECT_EQ(r.avoidMax, want.avoidMax);
    EXPECT_EQ(r.alphaThreshold, want.alphaThreshold);
    EXPECT_EQ(r.transparentAvoid, want.transparentAvoid);
    EXPECT_EQ(r.autoCover, want.autoCover);
}

TEST(ImageTargetKeys, FitDefaultsToContainAndCoverToAuto) {
    const RunSettings s = parse("");
    ASSERT_EQ(&s.target->kind(), &imageTargetKind);
    EXPECT_EQ(imageOf(s).fit, TargetFit::Contain);
    expectRule(imageOf(s).rule, PixelRule::forCover(TargetCover::Auto));
    EXPECT_TRUE(imageOf(s).rule.autoCover);  // the picture's transparency chooses when it is loaded
    PixelRule dark = PixelRule::forCover(TargetCover::Dark);
    dark.autoCover = true;  // whose ranges are the dark preset's
    expectRule(imageOf(s).rule, dark);
    expectRule(imageOf(parse("cover = \"auto\"\n")).rule, PixelRule::forCover(TargetCover::Auto));
    expectRule(imageOf(parse("alpha_threshold = 10\n")).rule, PixelRule::forCover(TargetCover::Auto, 10));
    EXPECT_EQ(imageOf(s).png, "/configs/logo.png");  // in the file: relative to the config
}

TEST(ImageTargetKeys, EveryFitIsAcceptedByNameAndAnotherNamesTheKey) {
    for (TargetFit f : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch, TargetFit::Exact})
        EXPECT_EQ(imageOf(parse(std::string("fit = \"") + targetFitName(f) + "\"\n")).fit, f);
    const InputError e = imageKeyError("fit = \"fill\"\n");
    EXPECT_EQ(e.file(), "/configs/x.toml");
    EXPECT_EQ(e.where(), "5:7");
    EXPECT_NE(e.message().find("target.fit must be \"contain\", \"cover\", \"stretch\" or \"exact\", got \"fill\""), std::string::npos)
        << e.message();
    const InputError set = imageKeyError("", {"target.fit=squash"});
    EXPECT_EQ(set.file(), "--set");
    EXPECT_NE(set.message().find("target.fit"), std::string::npos) << set.message();
    EXPECT_EQ(imageOf(parse("", {"target.fit=stretch"})).fit, TargetFit::Stretch);
}

TEST(ImageTargetKeys, ScaleIsAShareOfTheFrameForContainAndStretchOnly) {
    EXPECT_EQ(imageOf(parse("")).scale, 1.0);
    EXPECT_EQ(imageOf(parse("scale = 0.6\n")).scale, 0.6);
    EXPECT_EQ(imageOf(parse("scale = 0.5\nfit = \"stretch\"\n")).scale, 0.5);
    EXPECT_NE(imageKeyError("scale = 0\n").message().find("target.scale"), std::string::npos);
    EXPECT_NE(imageKeyError("scale = 1.5\n").message().find("target.scale"), std::string::npos);
    const InputError cover = imageKeyError("scale = 0.5\nfit = \"cover\"\n");
    EXPECT_NE(cover.message().find("only target.fit = \"contain\" or \"stretch\""), std::string::npos) << cover.message();
}

TEST(ImageTargetKeys, CoverPresetsSetTheRangesAndKeepTheAlphaThreshold) {
    expectRule(imageOf(parse("cover = \"light\"\n")).rule, PixelRule::forCover(TargetCover::Light));
    expectRule(imageOf(parse("cover = \"opaque\"\n")).rule, PixelRule::forCover(TargetCover::Opaque));
    expectRule(imageOf(parse("cover = \"opaque\"\nalpha_threshold = 10\n")).rule, PixelRule::forCover(TargetCover::Opaque, 10));
    expectRule(imageOf(parse("alpha_threshold = 10\ncover = \"light\"\n")).rule, PixelRule::forCover(TargetCover::Light, 10));
    expectRule(imageOf(parse("cover = \"dark\"\n", {"target.cover=opaque"})).rule, PixelRule::forCover(TargetCover::Opaque));
    expectRule(imageOf(parse("cover = \"dark\"\n")).rule, PixelRule{});  // dark, chosen: no auto
    const InputError e = imageKeyError("cover = \"alpha\"\n");
    EXPECT_EQ(e.where(), "5:9");
    EXPECT_NE(e.message().find("target.cover must be \"auto\", \"dark\", \"light\" or \"opaque\", got \"alpha\""), std::string::npos)
        << e.message();
}

TEST(ImageTargetKeys, CoverAndAnExplicitLuminanceRangeTogetherAreAnErrorNamingBoth) {
    const InputError e = imageKeyError("cover = \"light\"\nhit_max = 100\n");
    EXPECT_EQ(e.where(), "6:11");  // the later of the two keys
    EXPECT_NE(e.message().find("target.cover and target.hit_max both say which pixels to cover"), std::string::npos) << e.message();
    const InputError set = imageKeyError("avoid_min = 200\n", {"target.cover=opaque"});
    EXPECT_EQ(set.file(), "--set");
    EXPECT_NE(set.message().find("target.avoid_min"), std::string::npos) << set.message();
    EXPECT_NE(imageKeyError("cover = \"auto\"\nhit_min = 3\n").message().find("target.cover and target.hit_min"), std::string::npos);
    // without cover the ranges work as before, and say which pixels to cover: no auto
    const PixelRule r = imageOf(parse("hit_max = 80\navoid_min = 200\n")).rule;
    EXPECT_EQ(r.hitMax, 80);
    EXPECT_EQ(r.avoidMin, 200);
    EXPECT_FALSE(r.autoCover);
}

TEST(ImageTargetKeys, ARelativeImageGivenWithSetIsTakenFromTheCurrentDirectory) {
    const RunSettings s = parse("", {"target.image=my logo.png"});
    const std::string want = (std::filesystem::current_path() / "my logo.png").lexically_normal().string();
    EXPECT_EQ(imageOf(s).png, want);
    // recorded absolute in the stored config, so a resume (which re-reads that text) finds it
    EXPECT_NE(s.configText.find(want), std::string::npos) << s.configText;
    EXPECT_EQ(imageOf(parseConfig(s.configText, "/configs/x.toml")).png, want);
    EXPECT_EQ(imageOf(parse("", {"target.image=/abs/logo.png"})).png, "/abs/logo.png");
}

}  // namespace
}  // namespace shapevo
