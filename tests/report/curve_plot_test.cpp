// Curve plot: the SVG is well-formed, carries the axis numbers, labels and one polyline point per
// finite generation; the PNG draws the best curve where the data says; both files appear
// atomically and non-finite values never reach the output.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "report/curve_plot.hpp"
#include "base/input_error.hpp"
#include "report/plot_axes.hpp"
#include "../image/png_read.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

/// Generations 1..n, best rising from 1 to 10, mean below it with a shrinking spread.
std::vector<GenerationStats> risingCurve(int n) {
    std::vector<GenerationStats> curve;
    for (int g = 1; g <= n; ++g) {
        GenerationStats s;
        s.generation = std::uint32_t(g);
        s.seconds = 0.1 * g;
        s.evaluations = std::uint64_t(100 * g);
        s.best = 1.0 + 9.0 * (g - 1) / (n - 1);
        s.mean = s.best * 0.6;
        s.std = 1.0 / g;
        curve.push_back(s);
    }
    return curve;
}

/// Tags nest properly (a tiny XML check: no attributes containing '<' or '>' in our output).
bool wellFormed(const std::string& xml) {
    std::vector<std::string> open;
    for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
        const std::size_t end = xml.find('>', at);
        if (end == std::string::npos) return false;
        const std::string tag = xml.substr(at + 1, end - at - 1);
        if (tag.empty()) return false;
        if (tag[0] == '?' || tag.back() == '/') continue;  // declaration, self-closing
        const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" \n") - (tag[0] == '/' ? 1 : 0));
        if (tag[0] != '/') {
            open.push_back(name);
        } else {
            if (open.empty() || open.back() != name) return false;
            open.pop_back();
        }
    }
    return open.empty();
}

/// The value of attribute `points` of the first element with class `cls`.
std::string pointsOf(const std::string& svg, const std::string& cls) {
    const std::size_t el = svg.find("class=\"" + cls + "\"");
    if (el == std::string::npos) return {};
    const std::size_t p = svg.find("points=\"", el) + 8;
    return svg.substr(p, svg.find('"', p) - p);
}
std::size_t countOf(const std::string& s, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
    return n;
}

TEST(CurvePlot, SvgIsWellFormedWithAxisNumbersLabelsAndOnePointPerGeneration) {
    test::TempDir dir;
    const std::string path = dir.file("curve.svg");
    writeCurveSvg(risingCurve(50), path);
    const std::string svg = test::readFile(path);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_TRUE(wellFormed(svg)) << svg;
    EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_NE(svg.find(">generation</text>"), std::string::npos);
    EXPECT_NE(svg.find(">fitness</text>"), std::string::npos);
    EXPECT_NE(svg.find(">best</text>"), std::string::npos);
    for (const char* tick : {">0</text>", ">10</text>", ">50</text>"}) EXPECT_NE(svg.find(tick), std::string::npos) << tick;
    EXPECT_EQ(countOf(pointsOf(svg, "best"), ","), 50u);
    EXPECT_EQ(countOf(pointsOf(svg, "mean"), ","), 50u);
    EXPECT_EQ(countOf(pointsOf(svg, "band"), ","), 100u);  // upper edge forward, lower edge back
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1) << "no temporary left";
}

TEST(CurvePlot, BestPolylineRisesOnTheSvgPage) {
    test::TempDir dir;
    writeCurveSvg(risingCurve(5), dir.file("c.svg"));
    const std::string pts = pointsOf(test::readFile(dir.file("c.svg")), "best");
    double lastX = -1, lastY = 1e9;
    std::size_t at = 0;
    for (int i = 0; i < 5; ++i) {
        std::size_t used = 0;
        const double x = std::stod(pts.substr(at), &used);
        at += used + 1;
        const double y = std::stod(pts.substr(at), &used);
        at += used + 1;
        EXPECT_GT(x, lastX);
        EXPECT_LT(y, lastY) << "higher fitness is higher on the page (smaller y)";
        lastX = x, lastY = y;
    }
}

TEST(CurvePlot, NonFiniteValuesAreLeftOutAndEmptyCurvesStillPlot) {
    test::TempDir dir;
    auto curve = risingCurve(10);
    curve[3].best = std::numeric_limits<double>::quiet_NaN();
    curve[6].std = std::numeric_limits<double>::infinity();
    writeCurveSvg(curve, dir.file("c.svg"));
    const std::string svg = test::readFile(dir.file("c.svg"));
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(countOf(pointsOf(svg, "best"), ","), 9u);
    EXPECT_EQ(countOf(pointsOf(svg, "mean"), ","), 9u);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
    writeCurveSvg({}, dir.file("empty.svg"));
    const std::string empty = test::readFile(dir.file("empty.svg"));
    EXPECT_TRUE(wellFormed(empty));
    EXPECT_NE(empty.find("no data"), std::string::npos);
    writeCurvePng({}, dir.file("empty.png"));
    bool ok = false;
    test::readPngRgba(dir.file("empty.png"), ok);
    EXPECT_TRUE(ok);
}

TEST(CurvePlot, PngDrawsTheBestCurveRisingAndTheMeanBand) {
    test::TempDir dir;
    const std::string path = dir.file("curve.png");
    writeCurvePng(risingCurve(40), path);
    bool ok = false;
    const test::RgbaImage img = test::readPngRgba(path, ok);
    ASSERT_TRUE(ok);
    ASSERT_EQ(img.width, kCurvePlotWidth);
    ASSERT_EQ(img.height, kCurvePlotHeight);
    // best pixels (vermillion): mean height in the left and right quarters of the image
    double ySum[2] = {0, 0};
    int count[2] = {0, 0}, mean = 0, band = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const int r = img.at(x, y, 0), g = img.at(x, y, 1), b = img.at(x, y, 2);
            if (r == 213 && g == 94 && b == 0 && (x < img.width / 4 || x >= img.width * 3 / 4)) {
                ySum[x >= img.width / 2] += y;
                ++count[x >= img.width / 2];
            }
            mean += r == 0 && g == 114 && b == 178;
            band += b > r + 20 && r > 100 && r < 255;  // light blue: the band blended over white
        }
    ASSERT_GT(count[0], 10);
    ASSERT_GT(count[1], 10);
    EXPECT_LT(ySum[1] / count[1], ySum[0] / count[0] - 100) << "the best curve rises to the right";
    EXPECT_GT(mean, 300);
    EXPECT_GT(band, 1000);
}

TEST(CurvePlot, UnwritablePathThrowsInputError) {
    test::TempDir dir;
    EXPECT_THROW(writeCurveSvg(risingCurve(3), dir.file("no/dir/c.svg")), InputError);
    EXPECT_THROW(writeCurvePng(risingCurve(3), dir.file("no/dir/c.png")), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(PlotAxes, NiceAxisCoversTheDataWithRoundSteps) {
    const PlotAxis a = niceAxis(0.13, 0.91, 6, false);
    EXPECT_DOUBLE_EQ(a.step, 0.2);
    EXPECT_DOUBLE_EQ(a.lo, 0.0);
    EXPECT_NEAR(a.hi, 1.0, 1e-12);
    ASSERT_EQ(a.ticks.size(), 6u);
    EXPECT_EQ(tickLabel(a.ticks[3], a.step), "0.6");
    const PlotAxis g = niceAxis(1, 3, 8, true);
    EXPECT_EQ(g.step, 1.0) << "generations never get fractional ticks";
    const PlotAxis neg = niceAxis(-37, -2, 5, false);
    EXPECT_LE(neg.lo, -37);
    EXPECT_GE(neg.hi, -2);
    EXPECT_EQ(tickLabel(-40, 10), "-40");
    EXPECT_EQ(tickLabel(1e-17, 0.5), "0.0");
    EXPECT_EQ(tickLabel(2e9, 1e9), "2e+09");
}

TEST(PlotAxes, DegenerateRangesStillGiveAnIncreasingAxis) {
    for (const auto& [lo, hi] : {std::pair{5.0, 5.0}, std::pair{0.0, 0.0}, std::pair{1.0, 0.0},
                                 std::pair{std::nan(""), 1.0}, std::pair{-1e300, 1e300},
                                 std::pair{-1.7e308, 1.7e308}, std::pair{1e17, 1e17 + 16}}) {
        const PlotAxis a = niceAxis(lo, hi, 6, false);
        EXPECT_LT(a.lo, a.hi) << lo << " " << hi;
        EXPECT_GE(a.ticks.size(), 2u);
        EXPECT_LE(a.ticks.size(), 20u);
        if (lo <= hi && std::isfinite(hi - lo)) {  // otherwise the documented fallback [0, 1]
            EXPECT_LE(a.lo, lo);
            EXPECT_GE(a.hi, hi);
        }
    }
}

}  // namespace
}  // namespace shapevo
