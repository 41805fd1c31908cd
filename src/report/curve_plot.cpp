// Curve plot: one layout (data ranges, axes, pixel mapping) drawn twice, as SVG text and as pixels.
#include "report/curve_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "base/atomic_write.hpp"
#include "report/plot_axes.hpp"
#include "image/png_writer.hpp"
#include "image/rgba_canvas.hpp"

namespace shapevo {

namespace {

constexpr Rgba kBest{213, 94, 0, 255}, kMean{0, 114, 178, 255}, kBand{0, 114, 178, 64};
constexpr Rgba kAxis{0, 0, 0, 255}, kGrid{225, 225, 225, 255}, kWhite{255, 255, 255, 255};

/// The finite data and where it goes on the page.
struct Layout {
    std::vector<double> gen, best;            // points with a finite best
    std::vector<double> meanGen, mean, std;   // points with finite mean and std
    PlotAxis x, y;
    double left = 70, right = kCurvePlotWidth - 30, top = 40, bottom = kCurvePlotHeight - 50;
    double px(double v) const { return x.map(v, left, right); }
    double py(double v) const { return y.map(v, bottom, top); }
};

Layout layout(const std::vector<GenerationStats>& curve) {
    Layout l;
    double gLo = std::numeric_limits<double>::infinity(), gHi = -gLo, yLo = gLo, yHi = -gLo;
    for (const GenerationStats& s : curve) {
        const double g = s.generation;
        if (std::isfinite(s.best)) {
            l.gen.push_back(g), l.best.push_back(s.best);
            gLo = std::min(gLo, g), gHi = std::max(gHi, g), yLo = std::min(yLo, s.best), yHi = std::max(yHi, s.best);
        }
        if (std::isfinite(s.mean) && std::isfinite(s.std)) {
            const double sd = std::fabs(s.std);
            l.meanGen.push_back(g), l.mean.push_back(s.mean), l.std.push_back(sd);
            gLo = std::min(gLo, g), gHi = std::max(gHi, g);
            yLo = std::min(yLo, s.mean - sd), yHi = std::max(yHi, s.mean + sd);
        }
    }
    l.x = niceAxis(gLo, gHi, 8, true);
    l.y = niceAxis(yLo, yHi, 6, false);
    return l;
}

std::string num(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.2f", v);
    return s;
}
std::string colour(Rgba c) {
    char s[16];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", c[0], c[1], c[2]);
    return s;
}
std::string points(const Layout& l, const std::vector<double>& xs, const std::vector<double>& ys, double sign,
                   const std::vector<double>* offsets) {
    std::string out;
    for (std::size_t i = 0; i < xs.size(); ++i)
        out += num(l.px(xs[i])) + "," + num(l.py(ys[i] + (offsets ? sign * (*offsets)[i] : 0.0))) + " ";
    return out;
}

std::string svg(const Layout& l) {
    std::string s = R"(<?xml version="1.0" encoding="UTF-8"?>)" "\n";
    s += R"(<svg xmlns="http://www.w3.org/2000/svg" width=")" + std::to_string(kCurvePlotWidth) + R"(" height=")" +
         std::to_string(kCurvePlotHeight) + R"(" viewBox="0 0 )" + std::to_string(kCurvePlotWidth) + " " +
         std::to_string(kCurvePlotHeight) + R"(" font-family="sans-serif" font-size="12">)" "\n";
    s += "<title>shapevo fitness curve</title>\n";
    s += R"(<rect width="100%" height="100%" fill="white"/>)" "\n";
    s += R"(<g stroke=")" + colour(kGrid) + R"(" stroke-width="1">)" "\n";
    for (double t : l.x.ticks)
        s += R"(<line x1=")" + num(l.px(t)) + R"(" y1=")" + num(l.top) + R"(" x2=")" + num(l.px(t)) + R"(" y2=")" + num(l.bottom) + "\"/>\n";
    for (double t : l.y.ticks)
        s += R"(<line x1=")" + num(l.left) + R"(" y1=")" + num(l.py(t)) + R"(" x2=")" + num(l.right) + R"(" y2=")" + num(l.py(t)) + "\"/>\n";
    s += "</g>\n";
    if (!l.mean.empty()) {
        std::vector<double> revGen(l.meanGen.rbegin(), l.meanGen.rend()), revMean(l.mean.rbegin(), l.mean.rend()),
            revStd(l.std.rbegin(), l.std.rend());
        s += R"(<polygon class="band" fill=")" + colour(kBand) + R"(" fill-opacity="0.25" stroke="none" points=")" +
             points(l, l.meanGen, l.mean, 1, &l.std) + points(l, revGen, revMean, -1, &revStd) + "\"/>\n";
        s += R"(<polyline class="mean" fill="none" stroke=")" + colour(kMean) + R"(" stroke-width="1.5" stroke-dasharray="6 3" points=")" +
             points(l, l.meanGen, l.mean, 0, nullptr) + "\"/>\n";
    }
    if (!l.best.empty())
        s += R"(<polyline class="best" fill="none" stroke=")" + colour(kBest) + R"(" stroke-width="2" points=")" +
             points(l, l.gen, l.best, 0, nullptr) + "\"/>\n";
    if (l.best.size() == 1)  // a single point draws no line
        s += R"(<circle cx=")" + num(l.px(l.gen[0])) + R"(" cy=")" + num(l.py(l.best[0])) + R"(" r="3" fill=")" + colour(kBest) + "\"/>\n";
    // axes, ticks and labels
    s += R"(<g stroke="black" stroke-width="1"><line x1=")" + num(l.left) + R"(" y1=")" + num(l.bottom) + R"(" x2=")" +
         num(l.right) + R"(" y2=")" + num(l.bottom) + R"("/><line x1=")" + num(l.left) + R"(" y1=")" + num(l.top) +
         R"(" x2=")" + num(l.left) + R"(" y2=")" + num(l.bottom) + "\"/></g>\n";
    for (double t : l.x.ticks)
        s += R"(<line x1=")" + num(l.px(t)) + R"(" y1=")" + num(l.bottom) + R"(" x2=")" + num(l.px(t)) + R"(" y2=")" +
             num(l.bottom + 5) + R"(" stroke="black"/><text x=")" + num(l.px(t)) + R"(" y=")" + num(l.bottom + 18) +
             R"(" text-anchor="middle">)" + tickLabel(t, l.x.step) + "</text>\n";
    for (double t : l.y.ticks)
        s += R"(<line x1=")" + num(l.left - 5) + R"(" y1=")" + num(l.py(t)) + R"(" x2=")" + num(l.left) + R"(" y2=")" +
             num(l.py(t)) + R"(" stroke="black"/><text x=")" + num(l.left - 8) + R"(" y=")" + num(l.py(t) + 4) +
             R"(" text-anchor="end">)" + tickLabel(t, l.y.step) + "</text>\n";
    s += R"(<text x=")" + num((l.left + l.right) / 2) + R"(" y=")" + num(kCurvePlotHeight - 12.0) +
         R"(" text-anchor="middle">generation</text>)" "\n";
    s += R"x(<text transform="translate(16 )x" + num((l.top + l.bottom) / 2) +
         R"x() rotate(-90)" text-anchor="middle">fitness</text>)x" "\n";
    s += R"(<text x=")" + num(l.left) + R"(" y="24" font-size="14">shapevo fitness curve</text>)" "\n";
    // legend, top right
    const double lx = l.right - 150, ly = 18;
    s += R"(<line x1=")" + num(lx) + R"(" y1=")" + num(ly) + R"(" x2=")" + num(lx + 20) + R"(" y2=")" + num(ly) +
         R"(" stroke=")" + colour(kBest) + R"(" stroke-width="2"/><text x=")" + num(lx + 25) + R"(" y=")" + num(ly + 4) + "\">best</text>\n";
    s += R"(<rect x=")" + num(lx + 65) + R"(" y=")" + num(ly - 5) + R"(" width="20" height="10" fill=")" + colour(kBand) +
         R"(" fill-opacity="0.25"/><line x1=")" + num(lx + 65) + R"(" y1=")" + num(ly) + R"(" x2=")" + num(lx + 85) +
         R"(" y2=")" + num(ly) + R"(" stroke=")" + colour(kMean) + R"(" stroke-dasharray="6 3"/><text x=")" + num(lx + 90) +
         R"(" y=")" + num(ly + 4) + "\">mean &#177; std</text>\n";
    if (l.best.empty() && l.mean.empty())
        s += R"(<text x=")" + num((l.left + l.right) / 2) + R"(" y=")" + num((l.top + l.bottom) / 2) +
             R"(" text-anchor="middle" fill="gray">no data</text>)" "\n";
    return s + "</svg>\n";
}

void polyline(RgbaCanvas& c, const Layout& l, const std::vector<double>& xs, const std::vector<double>& ys, Rgba colour,
              int thickness) {
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        c.line(l.px(xs[i]), l.py(ys[i]), l.px(xs[i + 1]), l.py(ys[i + 1]), colour, thickness);
    if (xs.size() == 1) c.rect(int(l.px(xs[0])) - 2, int(l.py(ys[0])) - 2, int(l.px(xs[0])) + 2, int(l.py(ys[0])) + 2, colour);
}

/// The band between mean - std and mean + std, each pixel column blended once.
void band(RgbaCanvas& c, const Layout& l) {
    for (std::size_t i = 0; i + 1 < l.meanGen.size(); ++i) {
        const double x0 = l.px(l.meanGen[i]), x1 = l.px(l.meanGen[i + 1]);
        if (!(x1 > x0)) continue;
        const int last = i + 2 == l.meanGen.size() ? int(std::floor(x1)) : int(std::ceil(x1)) - 1;
        for (int x = int(std::ceil(x0)); x <= last; ++x) {
            const double t = (x - x0) / (x1 - x0);
            const double m = l.mean[i] + (l.mean[i + 1] - l.mean[i]) * t, sd = l.std[i] + (l.std[i + 1] - l.std[i]) * t;
            c.span(x, int(std::lround(l.py(m + sd))), int(std::lround(l.py(m - sd))), kBand);
        }
    }
}

RgbaCanvas raster(const Layout& l) {
    RgbaCanvas c(kCurvePlotWidth, kCurvePlotHeight, kWhite);
    for (double t : l.x.ticks) c.line(l.px(t), l.top, l.px(t), l.bottom, kGrid);
    for (double t : l.y.ticks) c.line(l.left, l.py(t), l.right, l.py(t), kGrid);
    band(c, l);
    polyline(c, l, l.meanGen, l.mean, kMean, 1);
    polyline(c, l, l.gen, l.best, kBest, 2);
    c.line(l.left, l.bottom, l.right, l.bottom, kAxis);
    c.line(l.left, l.top, l.left, l.bottom, kAxis);
    constexpr int scale = 2;
    for (double t : l.x.ticks) {
        c.line(l.px(t), l.bottom, l.px(t), l.bottom + 5, kAxis);
        const std::string label = tickLabel(t, l.x.step);
        c.text(int(l.px(t)) - RgbaCanvas::textWidth(label, scale) / 2, int(l.bottom) + 9, label, kAxis, scale);
    }
    for (double t : l.y.ticks) {
        c.line(l.left - 5, l.py(t), l.left, l.py(t), kAxis);
        const std::string label = tickLabel(t, l.y.step);
        c.text(int(l.left) - 8 - RgbaCanvas::textWidth(label, scale), int(l.py(t)) - RgbaCanvas::textHeight(scale) / 2,
               label, kAxis, scale);
    }
    return c;
}

}  // namespace

void writeCurveSvg(const std::vector<GenerationStats>& curve, const std::string& path) {
    const std::string text = svg(layout(curve));
    writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
}

void writeCurvePng(const std::vector<GenerationStats>& curve, const std::string& path) {
    const RgbaCanvas c = raster(layout(curve));
    writePngRgba(path, c.width(), c.height(), c.pixels());
}

}  // namespace shapevo
