// Curve plot: the SVG is well-formed and carries its title, axis labels, legend texts and the
// numbers of a logarithmic time axis; one polyline point per generation (fewer only where a long
// run has more generations than pixels); the IoU series and its right axis appear when rows carry
// an IoU; the PNG has the promised size and draws the same picture; both files appear atomically;
// one row, equal values, zero times and non-finite values never break a plot.
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

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Generations 1..n at 0.1 s each, best rising from 1 to 10, mean below it with a shrinking
/// spread; with `iou`, the IoU rises from 0.1 to 0.9.
std::vector<GenerationStats> risingCurve(int n, bool iou = false) {
    std::vector<GenerationStats> curve;
    for (int g = 1; g <= n; ++g) {
        GenerationStats s;
        s.generation = std::uint32_t(g);
        s.seconds = 0.1 * g;
        s.evaluations = std::uint64_t(100 * g);
        s.best = n > 1 ? 1.0 + 9.0 * (g - 1) / (n - 1) : 1.0;
        s.mean = s.best * 0.6;
        s.std = 1.0 / g;
        if (iou) s.iou = n > 1 ? 0.1 + 0.8 * (g - 1) / (n - 1) : 0.5;
        curve.push_back(s);
    }
    return curve;
}

CurvePlotLabels treeLabels() {
    CurvePlotLabels l;
    l.title = "tree-logo: targets/tree-logo.png";
    l.iouName = "silhouette IoU";
    return l;
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
std::vector<std::pair<double, double>> parsePoints(const std::string& pts) {
    std::vector<std::pair<double, double>> out;
    std::size_t at = 0;
    while (at < pts.size()) {
        std::size_t used = 0;
        const double x = std::stod(pts.substr(at), &used);
        at += used + 1;
        const double y = std::stod(pts.substr(at), &used);
        at += used + 1;
        out.emplace_back(x, y);
    }
    return out;
}
std::size_t countOf(const std::string& s, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
    return n;
}
bool hasText(const std::string& svg, const std::string& text) { return svg.find(">" + text + "</text>") != std::string::npos; }

/// The SVG of `curve` (written into a temporary folder of its own, removed on return).
std::string svgOf(const std::vector<GenerationStats>& curve, const CurvePlotLabels& labels = treeLabels()) {
    test::TempDir dir;
    writeCurveSvg(curve, labels, dir.file("c.svg"));
    return test::readFile(dir.file("c.svg"));
}

TEST(CurvePlot, SvgHasTitleAxisLabelsLegendAndLogTimeTicks) {
    test::TempDir dir;
    const std::string path = dir.file("curve.svg");
    writeCurveSvg(risingCurve(50, true), treeLabels(), path);
    const std::string svg = test::readFile(path);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_TRUE(wellFormed(svg)) << svg;
    EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_NE(svg.find("<title>tree-logo: targets/tree-logo.png</title>"), std::string::npos);
    for (const char* t : {"tree-logo: targets/tree-logo.png", "seconds (log scale)", "fitness", "best fitness",
                          "mean \u00b1 std of the population", "silhouette IoU of the best (right axis)",
                          "silhouette IoU of the best"})
        EXPECT_TRUE(hasText(svg, t)) << t;
    // 0.1 s .. 5 s: every 1, 2 and 5 of the decades in between, and nothing linear like 3 or 4
    for (const char* tick : {"0.1", "0.2", "0.5", "1", "2", "5"}) EXPECT_TRUE(hasText(svg, tick)) << tick;
    for (const char* tick : {"3", "0.3", "1.5"}) EXPECT_FALSE(hasText(svg, tick)) << tick;
    for (const char* tick : {"0.0", "0.4", "1.0"}) EXPECT_TRUE(hasText(svg, tick)) << "IoU axis " << tick;
    EXPECT_EQ(countOf(pointsOf(svg, "best"), ","), 50u);
    EXPECT_EQ(countOf(pointsOf(svg, "mean"), ","), 50u);
    EXPECT_EQ(countOf(pointsOf(svg, "iou"), ","), 50u);
    EXPECT_EQ(countOf(pointsOf(svg, "band"), ","), 100u);  // upper edge forward, lower edge back
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1) << "no temporary left";
}

TEST(CurvePlot, TimeIsLogarithmicSoEachDecadeGetsTheSameWidth) {
    std::vector<GenerationStats> curve = risingCurve(4);
    for (int i = 0; i < 4; ++i) curve[std::size_t(i)].seconds = std::pow(10.0, i);  // 1, 10, 100, 1000 s
    const auto pts = parsePoints(pointsOf(svgOf(curve), "best"));
    ASSERT_EQ(pts.size(), 4u);
    const double decade = pts[1].first - pts[0].first;
    EXPECT_GT(decade, 100);
    EXPECT_NEAR(pts[2].first - pts[1].first, decade, 0.02);
    EXPECT_NEAR(pts[3].first - pts[2].first, decade, 0.02);
}

TEST(CurvePlot, WithoutIoUThereIsNoIoUSeriesOrAxis) {
    const std::string svg = svgOf(risingCurve(10));
    EXPECT_TRUE(pointsOf(svg, "iou").empty());
    EXPECT_EQ(svg.find("IoU of the best"), std::string::npos);
    EXPECT_TRUE(hasText(svg, "best fitness"));
}

TEST(CurvePlot, BestPolylineRisesOnTheSvgPage) {
    const auto pts = parsePoints(pointsOf(svgOf(risingCurve(5)), "best"));
    ASSERT_EQ(pts.size(), 5u);
    for (std::size_t i = 1; i < pts.size(); ++i) {
        EXPECT_GT(pts[i].first, pts[i - 1].first);
        EXPECT_LT(pts[i].second, pts[i - 1].second) << "higher fitness is higher on the page (smaller y)";
    }
}

TEST(CurvePlot, ZeroSecondsSitAtTheFirstPositiveTimeAndNoTimeFallsBackToGenerations) {
    auto curve = risingCurve(5);
    curve[0].seconds = 0;
    const auto pts = parsePoints(pointsOf(svgOf(curve), "best"));
    ASSERT_EQ(pts.size(), 5u);
    EXPECT_EQ(pts[0].first, pts[1].first);
    for (auto& s : curve) s.seconds = 0;
    const std::string svg = svgOf(curve);
    EXPECT_TRUE(hasText(svg, "generation (log scale)"));
    EXPECT_EQ(countOf(pointsOf(svg, "best"), ","), 5u);
    CurvePlotLabels byGeneration = treeLabels();
    byGeneration.timeAxis = CurveTimeAxis::Generations;
    EXPECT_TRUE(hasText(svgOf(risingCurve(5), byGeneration), "generation (log scale)"));
}

TEST(CurvePlot, NonFiniteValuesAreLeftOutAndEmptyOneRowAndFlatCurvesStillPlot) {
    auto curve = risingCurve(10, true);
    curve[3].best = kNaN;
    curve[6].std = std::numeric_limits<double>::infinity();
    curve[8].iou = kNaN;
    curve[9].seconds = kNaN;  // no place on the time axis: the whole row is left out
    const std::string svg = svgOf(curve);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(countOf(pointsOf(svg, "best"), ","), 8u);
    EXPECT_EQ(countOf(pointsOf(svg, "mean"), ","), 8u);
    EXPECT_EQ(countOf(pointsOf(svg, "iou"), ","), 8u);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
    const std::string empty = svgOf({});
    EXPECT_TRUE(wellFormed(empty));
    EXPECT_TRUE(hasText(empty, "no data"));
    const std::string one = svgOf(risingCurve(1, true));
    EXPECT_TRUE(wellFormed(one));
    EXPECT_EQ(countOf(pointsOf(one, "best"), ","), 1u);
    EXPECT_NE(one.find("<circle"), std::string::npos) << "a single point is drawn as a dot";
    auto flat = risingCurve(20);
    for (auto& s : flat) s.best = s.mean = 3, s.std = 0;
    EXPECT_TRUE(wellFormed(svgOf(flat)));
    test::TempDir dir;  // after svgOf's: a test's temporary folders share one name
    for (const auto& c : {std::vector<GenerationStats>{}, risingCurve(1, true), flat, curve}) {
        writeCurvePng(c, treeLabels(), dir.file("c.png"));
        bool ok = false;
        test::readPngRgba(dir.file("c.png"), ok);
        EXPECT_TRUE(ok);
    }
}

TEST(CurvePlot, LongRunsKeepAboutOnePointPerPixelAndTheirLastPoint) {
    std::vector<GenerationStats> curve;
    for (int g = 1; g <= 200000; ++g) {
        GenerationStats s;
        s.generation = std::uint32_t(g), s.seconds = 0.003 * g, s.best = std::log(double(g)), s.mean = 0, s.std = 1;
        curve.push_back(s);
    }
    const auto pts = parsePoints(pointsOf(svgOf(curve), "best"));
    EXPECT_LT(pts.size(), 4000u);
    EXPECT_GT(pts.size(), 300u);
    const auto all = parsePoints(pointsOf(svgOf({curve.front(), curve.back()}), "best"));
    EXPECT_EQ(pts.back(), all.back()) << "the last generation is always drawn";
}

TEST(CurvePlot, PngHasThePlotSizeTitleTextAndTheRisingCurves) {
    test::TempDir dir;
    const std::string path = dir.file("curve.png");
    writeCurvePng(risingCurve(40, true), treeLabels(), path);
    bool ok = false;
    const test::RgbaImage img = test::readPngRgba(path, ok);
    ASSERT_TRUE(ok);
    ASSERT_EQ(img.width, kCurvePlotWidth);
    ASSERT_EQ(img.height, kCurvePlotHeight);
    auto near = [&](int x, int y, int r, int g, int b) {
        return std::abs(img.at(x, y, 0) - r) < 30 && std::abs(img.at(x, y, 1) - g) < 30 && std::abs(img.at(x, y, 2) - b) < 30;
    };
    // best (vermillion) and IoU (green): mean height in the left and right quarters of the plot
    double best[2] = {0, 0}, iou[2] = {0, 0};
    int bestN[2] = {0, 0}, iouN[2] = {0, 0}, title = 0, band = 0;
    for (int y = 70; y < img.height - 60; ++y)
        for (int x = 0; x < img.width; ++x) {
            const bool left = x > 80 && x < img.width / 4, right = x >= img.width * 3 / 4 && x < img.width - 80;
            if (!left && !right) continue;
            if (near(x, y, 213, 94, 0)) best[right] += y, ++bestN[right];
            if (near(x, y, 0, 158, 115)) iou[right] += y, ++iouN[right];
            band += img.at(x, y, 2) > img.at(x, y, 0) + 20 && img.at(x, y, 0) > 100;  // light blue over white
        }
    for (int y = 0; y < 34; ++y)
        for (int x = 0; x < img.width; ++x) title += img.at(x, y, 0) < 100;
    for (int side = 0; side < 2; ++side) {
        ASSERT_GT(bestN[side], 10);
        ASSERT_GT(iouN[side], 10);
    }
    EXPECT_LT(best[1] / bestN[1], best[0] / bestN[0] - 100) << "the best curve rises to the right";
    EXPECT_LT(iou[1] / iouN[1], iou[0] / iouN[0] - 100) << "the IoU curve rises to the right";
    EXPECT_GT(band, 1000);
    EXPECT_GT(title, 200) << "the title is drawn in dark text";
}

TEST(CurvePlot, UnwritablePathThrowsInputError) {
    test::TempDir dir;
    EXPECT_THROW(writeCurveSvg(risingCurve(3), treeLabels(), dir.file("no/dir/c.svg")), InputError);
    EXPECT_THROW(writeCurvePng(risingCurve(3), treeLabels(), dir.file("no/dir/c.png")), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(CurvePlot, TitleIsEscapedForXml) {
    CurvePlotLabels labels = treeLabels();
    labels.title = "a <b> & \"c\"";
    const std::string svg = svgOf(risingCurve(3), labels);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
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

TEST(PlotAxes, LogAxisTicksAreOneTwoFiveOfEachDecade) {
    const LogAxis a = logAxis(0.13, 540);
    EXPECT_DOUBLE_EQ(a.lo, 0.1);
    EXPECT_DOUBLE_EQ(a.hi, 1000);
    ASSERT_EQ(a.ticks.size(), 13u);  // 0.1 0.2 0.5 1 2 5 10 20 50 100 200 500 1000
    std::vector<std::string> labelled;
    for (std::size_t i = 0; i < a.ticks.size(); ++i)
        if (a.labelled[i]) labelled.push_back(logTickLabel(a.ticks[i]));
    EXPECT_EQ(labelled, (std::vector<std::string>{"0.1", "1", "10", "100", "1000"})) << "four decades: powers of ten only";
    const LogAxis b = logAxis(0.2, 5);
    EXPECT_DOUBLE_EQ(b.lo, 0.2) << "a tick is its own bound";
    EXPECT_DOUBLE_EQ(b.hi, 5);
    EXPECT_EQ(std::count(b.labelled.begin(), b.labelled.end(), true), 5) << "few decades: every tick numbered";
    EXPECT_NEAR(a.map(10, 0, 400), 200, 1e-9);
    EXPECT_EQ(logTickLabel(0.05), "0.05");
    EXPECT_EQ(logTickLabel(2000), "2000");
}

TEST(PlotAxes, DegenerateLogRangesStillGiveAnIncreasingAxis) {
    for (const auto& [lo, hi] : {std::pair{3.0, 3.0}, std::pair{0.0, 0.0}, std::pair{-1.0, 5.0}, std::pair{5.0, 1.0},
                                 std::pair{std::nan(""), 1.0}, std::pair{1e-320, 1e308}, std::pair{2.0, 2.0}}) {
        const LogAxis a = logAxis(lo, hi);
        EXPECT_LT(a.lo, a.hi) << lo << " " << hi;
        EXPECT_GE(a.ticks.size(), 2u);
        EXPECT_EQ(a.ticks.size(), a.labelled.size());
        if (lo > 0 && lo <= hi && lo >= 1e-300) {
            EXPECT_LE(a.lo, lo * (1 + 1e-12));
            EXPECT_GE(a.hi, hi * (1 - 1e-12));
        }
    }
}

}  // namespace
}  // namespace shapevo
