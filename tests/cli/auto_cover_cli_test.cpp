// target.cover = "auto", the default, end to end: a white logo on transparency (a 256 x 256
// palette PNG with a tRNS chunk) runs through configs/tree-logo.toml with no cover flag, and the
// run's first line says which preset auto chose and why; a black logo on white says "dark".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "../image/png_test_util.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::runShapevo;
using test::sourcePath;
using test::TempDir;

/// A 256 x 256 palette PNG: a disc of palette entry `ink` on entry 1 - ink; entry 0 is white,
/// entry 1 black, their alpha `alpha` (a tRNS chunk unless empty).
void writeAutoCoverCliLogo(const std::string& path, int ink, std::vector<std::uint8_t> alpha) {
    test::writeTwoEntryPalettePng(path, ink, std::move(alpha), [](int x, int y) { return std::hypot(x - 128, y - 128) < 90; });
}

const std::string kAutoCoverSmall = " --set ga.population=20 --set ga.elitism=4 --set ga.generations=2 --threads 1";

TEST(AutoCoverCli, AWhiteLogoOnTransparencyRunsWithNoFlagAndTheFirstLineSaysOpaque) {
    TempDir dir;
    writeAutoCoverCliLogo(dir.file("logo.png"), 0, {255, 0});  // white disc, transparent background
    const auto r = runShapevo("run " + sourcePath("configs/tree-logo.toml") + " --set target.image=" + dir.file("logo.png") +
                              " --out " + dir.file("run") + kAutoCoverSmall);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string first = r.output.substr(0, r.output.find('\n'));
    EXPECT_NE(first.find("shapevo run tree-logo: "), std::string::npos) << first;
    EXPECT_NE(first.find(", cover: auto → opaque (the picture has transparency), "), std::string::npos) << first;
}

TEST(AutoCoverCli, ABlackLogoOnWhiteIsCoveredWhereDarkAndAnExplicitPresetIsNotReported) {
    TempDir dir;
    writeAutoCoverCliLogo(dir.file("logo.png"), 1, {});  // black disc on white, no transparency
    const std::string run = "run " + sourcePath("configs/tree-logo.toml") + " --set target.image=" + dir.file("logo.png") + kAutoCoverSmall;
    const auto r = runShapevo(run + " --out " + dir.file("auto"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.substr(0, r.output.find('\n')).find(", cover: auto → dark (the picture has no transparency), "),
              std::string::npos)
        << r.output;
    const auto chosen = runShapevo(run + " --set target.cover=dark --out " + dir.file("dark"));
    ASSERT_EQ(chosen.exitCode, 0) << chosen.output;
    EXPECT_EQ(chosen.output.find("cover: auto"), std::string::npos) << chosen.output;
    // the same target either way: the same run
    EXPECT_EQ(test::readFile(dir.file("auto/best.genome")), test::readFile(dir.file("dark/best.genome")));
}

}  // namespace
}  // namespace shapevo
