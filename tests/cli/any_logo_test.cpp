// Any logo (issue 14): the shipped tree and city configs take a PNG of any size and shape through
// `--set target.image=...` alone (target.cover = "auto", the default, covers the opaque pixels of a
// logo on a transparent background and the dark ones of any other): logos made here (a 229 x 304 disc, a 400 x 150 bar, a 256 x 256 white star on
// transparency) are fitted into the 800 x 600 frame and a short run's silhouette IoU rises above
// a floor. A relative --set path is taken from the current directory and a resume finds the same
// target; a 1 x 1 or 30000 x 30000 PNG is one clear message and exit 2, creating nothing.
//
// The floors were measured at seeds 1-5 with these settings (tree-logo with its target.scale =
// 0.45): the worst IoUs were tree-logo + disc 0.797, city-whale + bar 0.575, tree-logo + star 0.520
// (seed 1, the one run here: 0.875, 0.596, 0.675), against 0.68-0.70, 0.38-0.42 and 0.47-0.51 for
// the best of the initial population (generation 1, seeds 1-3). The disc and bar floors lie
// between the two; the star's (0.55) lies above seed 3's 0.520, which stays near its start, and
// well below seed 1's. A run that does not improve on its random start fails, and one no better
// than the old code (exit 2, or IoU 0) certainly does.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../image/png_test_util.hpp"
#include "../test_support.hpp"
#include "image/png_writer.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

/// A w x h RGBA logo: inside(x, y) pixels get `ink`, the others `paper`.
template <class Inside>
void writeLogo(const std::string& path, int w, int h, Inside inside, std::array<std::uint8_t, 4> ink,
               std::array<std::uint8_t, 4> paper) {
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto& c = inside(x, y) ? ink : paper;
            rgba.insert(rgba.end(), c.begin(), c.end());
        }
    writePngRgba(path, w, h, rgba);
}

constexpr std::array<std::uint8_t, 4> kBlack{0, 0, 0, 255}, kWhite{255, 255, 255, 255}, kClear{0, 0, 0, 0};

double iouOf(const std::string& folder) {
    const std::string s = readFile(folder + "/summary.json");
    const auto at = s.find("\"silhouette_iou\": ");
    if (at == std::string::npos) return -1;
    return std::stod(s.substr(at + 18));
}

/// Run `config` on the logo `logo` (written by `write` into a fresh folder) with `overrides`;
/// require exit 0, the fitted-placement note and a silhouette IoU above `floor`.
template <class Write>
void expectIoUAbove(const char* config, const char* logo, Write write, const std::string& overrides, double floor) {
    TempDir dir;
    write(dir.file(logo));
    const std::string out = dir.file("run");
    const auto r = runShapevo("run " + sourcePath(std::string("configs/") + config + ".toml") + " --set target.image=" +
                              dir.file(logo) + overrides + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("fitted (contain) into 800x600"), std::string::npos) << r.output;
    const double iou = iouOf(out);
    EXPECT_GT(iou, floor);
    std::printf("[ any logo ] %s + %s: silhouette IoU %.4f (floor %.2f)\n", config, logo, iou, floor);
}

TEST(AnyLogo, TreeLogoConfigGrowsATreeWhoseShadowIsATallDisc) {
    expectIoUAbove("tree-logo", "disc.png", [](const std::string& path) {
        writeLogo(path, 229, 304, [](int x, int y) { return std::hypot(x - 114, y - 152) < 100; }, kBlack, kWhite);
    }, " --set ga.generations=25", 0.75);
}

TEST(AnyLogo, CityWhaleConfigBuildsASkylineShapedLikeAWideBar) {
    expectIoUAbove("city-whale", "bar.png", [](const std::string& path) {
        writeLogo(path, 400, 150, [](int x, int y) { return x > 20 && x < 380 && y > 30 && y < 120; }, kBlack, kWhite);
    }, " --set ga.generations=40", 0.50);
}

TEST(AnyLogo, TreeLogoConfigCoversTheOpaquePixelsOfAWhiteStarOnTransparency) {
    expectIoUAbove("tree-logo", "star.png", [](const std::string& path) {
        writeLogo(path, 256, 256, [](int x, int y) {
            return std::hypot(x - 128, y - 128) < 60 + 40 * std::cos(5 * std::atan2(y - 128.0, x - 128.0));
        }, kWhite, kClear);
    }, " --set ga.generations=25", 0.55);  // no cover flag: target.cover = "auto" sees the transparency
}

TEST(AnyLogo, ARelativeLogoIsTakenFromTheCurrentDirectoryAndAResumeFindsTheSameTarget) {
    TempDir dir;
    writeLogo(dir.file("logo.png"), 300, 120, [](int x, int y) { return y > 40 && (x / 30) % 2 == 0; }, kBlack, kWhite);
    const std::string cfg = sourcePath("configs/city-whale.toml");
    const std::string small = " --set ga.population=30 --set ga.elitism=6 --set checkpoint.interval=3 -q";
    const std::string inDir = "cd '" + dir.path().string() + "' && " + std::string(SHAPEVO_BIN);
    auto r = test::runCommand(inDir + " run " + cfg + " --set target.image=logo.png --out whole --set ga.generations=6" + small);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = test::runCommand(inDir + " run " + cfg + " --set target.image=logo.png --out split --set ga.generations=3" + small);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runShapevo("resume " + dir.file("split") + " --generations 6 -q");  // from another directory
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readFile(dir.file("whole/best.genome")), readFile(dir.file("split/best.genome")));
    EXPECT_NE(readFile(dir.file("split/config.toml")).find(dir.file("logo.png")), std::string::npos);
}

TEST(AnyLogo, TinyAndHugePngsAreOneClearMessageAndExit2CreatingNothing) {
    TempDir dir;
    writeLogo(dir.file("one.png"), 1, 1, [](int, int) { return true; }, kBlack, kWhite);
    test::writeFile(dir.file("huge.png"), test::forgedHugePng(dir.file("scratch.png"), 30000, 30000));
    const struct {
        const char* file;
        const char* message;
    } cases[] = {
        {"one.png", "one.png: the image is 1 x 1 pixels, too small for a target: it needs at least 8 pixels on a side"},
        {"huge.png", "huge.png: the image is 30000 x 30000 pixels, over the size limit of 16384 pixels on a side and 67108864"},
    };
    for (const auto& c : cases) {
        const std::string out = dir.file(std::string("out-") + c.file);
        const auto r = runShapevo("run " + sourcePath("configs/tree-logo.toml") + " --set target.image=" + dir.file(c.file) +
                                  " --out " + out);
        EXPECT_EQ(r.exitCode, 2) << c.file << ": " << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.file;
    }
}

}  // namespace
}  // namespace shapevo
