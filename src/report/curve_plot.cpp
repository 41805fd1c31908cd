// Curve plot: the data is sorted into series and axes once (Layout), then drawn by one function
// onto either painter, so the SVG and the PNG show the same picture.
#include "report/curve_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/atomic_write.hpp"
#include "report/cairo_painter.hpp"
#include "report/plot_axes.hpp"
#include "report/svg_painter.hpp"

namespace shapevo {

namespace {

constexpr PlotColour kBest{213, 94, 0}, kMean{0, 114, 178}, kBand{0, 114, 178, 0.25}, kIoU{0, 158, 115};
constexpr PlotColour kInk{0, 0, 0}, kGrid{225, 225, 225}, kMinorGrid{242, 242, 242}, kMuted{110, 110, 110};
constexpr double kLeft = 78, kRight = kCurvePlotWidth - 72, kTop = 66, kBottom = kCurvePlotHeight - 58;
constexpr double kFont = 12;

/// The finite data, one x per row (clamped to the axis), and the axes.
struct Layout {
    std::vector<double> x, best, xMean, mean, std, xIoU, iou;
    bool generations = false;  ///< the x axis counts generations, not seconds
    LogAxis xAxis;
    PlotAxis yAxis;
    double px(double v) const { return xAxis.map(v, kLeft, kRight); }
    double py(double v) const { return yAxis.map(v, kBottom, kTop); }
    double pIoU(double v) const { return kBottom + std::clamp(v, 0.0, 1.0) * (kTop - kBottom); }
};

Layout layout(const std::vector<GenerationStats>& curve, CurveTimeAxis wanted) {
    Layout l;
    auto positiveMin = [&](bool byGeneration) {
        double m = std::numeric_limits<double>::infinity();
        for (const GenerationStats& s : curve) {
            const double v = byGeneration ? double(s.generation) : s.seconds;
            if (std::isfinite(v) && v > 0) m = std::min(m, v);
        }
        return m;
    };
    l.generations = wanted == CurveTimeAxis::Generations || !std::isfinite(positiveMin(false));
    const double floor = positiveMin(l.generations);  // zero times sit at the first positive one
    double xLo = std::numeric_limits<double>::infinity(), xHi = -xLo, yLo = xLo, yHi = -xLo;
    for (const GenerationStats& s : curve) {
        double x = l.generations ? double(s.generation) : s.seconds;
        if (!std::isfinite(x) || !std::isfinite(floor)) continue;
        x = std::max(x, floor);
        bool used = false;
        if (std::isfinite(s.best)) {
            l.x.push_back(x), l.best.push_back(s.best), used = true;
            yLo = std::min(yLo, s.best), yHi = std::max(yHi, s.best);
        }
        const double sd = std::fabs(s.std);
        if (std::isfinite(s.mean) && std::isfinite(sd) && std::isfinite(s.mean - sd) && std::isfinite(s.mean + sd)) {
            l.xMean.push_back(x), l.mean.push_back(s.mean), l.std.push_back(sd), used = true;
            yLo = std::min(yLo, s.mean - sd), yHi = std::max(yHi, s.mean + sd);
        }
        if (std::isfinite(s.iou)) l.xIoU.push_back(x), l.iou.push_back(s.iou), used = true;
        if (used) xLo = std::min(xLo, x), xHi = std::max(xHi, x);
    }
    l.xAxis = logAxis(xLo, xHi);
    l.yAxis = niceAxis(yLo, yHi, 6, false);
    return l;
}

/// Page points of a series, leaving out points within half a pixel of the last one kept (a long
/// run has more generations than the page has pixels); the last point is always kept.
PlotPainter::Points pagePoints(const std::vector<double>& xs, const std::vector<double>& ys, const Layout& l,
                               double (Layout::*toY)(double) const) {
    PlotPainter::Points out;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const std::pair<double, double> p{l.px(xs[i]), (l.*toY)(ys[i])};
        const bool last = i + 1 == xs.size();
        if (!out.empty() && !last && std::fabs(p.first - out.back().first) < 0.5 && std::fabs(p.second - out.back().second) < 0.5)
            continue;
        out.push_back(p);
    }
    return out;
}

void series(PlotPainter& p, const PlotPainter::Points& pts, PlotColour c, double width, bool dashed, const std::string& name) {
    p.polyline(pts, c, width, dashed, name);
    if (pts.size() == 1) p.circle(pts[0].first, pts[0].second, 3, c);  // one point draws no line
}

/// `title` shortened with "..." until it fits `width` pixels.
std::string fitted(PlotPainter& p, std::string title, double width, double size) {
    if (p.textWidth(title, size, true) <= width) return title;
    while (!title.empty() && p.textWidth(title + "...", size, true) > width) title.pop_back();
    return title + "...";
}

void draw(PlotPainter& p, const Layout& l, const CurvePlotLabels& labels) {
    const bool withIoU = !l.iou.empty();
    // grid
    for (std::size_t i = 0; i < l.xAxis.ticks.size(); ++i) {
        const double x = l.px(l.xAxis.ticks[i]);
        p.line(x, kTop, x, kBottom, l.xAxis.labelled[i] ? kGrid : kMinorGrid);
    }
    for (double t : l.yAxis.ticks) p.line(kLeft, l.py(t), kRight, l.py(t), kGrid);
    // data: band, mean, best, IoU
    if (!l.mean.empty()) {
        std::vector<double> upper(l.mean.size()), lower(l.mean.size());
        for (std::size_t i = 0; i < l.mean.size(); ++i) upper[i] = l.mean[i] + l.std[i], lower[i] = l.mean[i] - l.std[i];
        PlotPainter::Points band = pagePoints(l.xMean, upper, l, &Layout::py);
        const PlotPainter::Points back = pagePoints(l.xMean, lower, l, &Layout::py);
        band.insert(band.end(), back.rbegin(), back.rend());
        p.polygon(band, kBand, "band");
        series(p, pagePoints(l.xMean, l.mean, l, &Layout::py), kMean, 1.5, true, "mean");
    }
    series(p, pagePoints(l.x, l.best, l, &Layout::py), kBest, 2, false, "best");
    if (withIoU) series(p, pagePoints(l.xIoU, l.iou, l, &Layout::pIoU), kIoU, 1.5, false, "iou");
    // axes with ticks and numbers
    p.line(kLeft, kBottom, kRight, kBottom, kInk);
    p.line(kLeft, kTop, kLeft, kBottom, kInk);
    for (std::size_t i = 0; i < l.xAxis.ticks.size(); ++i) {
        const double x = l.px(l.xAxis.ticks[i]);
        p.line(x, kBottom, x, kBottom + (l.xAxis.labelled[i] ? 5 : 3), kInk);
        if (l.xAxis.labelled[i])
            p.text(x, kBottom + 18, logTickLabel(l.xAxis.ticks[i]), {kFont, TextAnchor::Middle});
    }
    for (double t : l.yAxis.ticks) {
        p.line(kLeft - 5, l.py(t), kLeft, l.py(t), kInk);
        p.text(kLeft - 8, l.py(t) + 4, tickLabel(t, l.yAxis.step), {kFont, TextAnchor::End});
    }
    PlotText axisLabel{13, TextAnchor::Middle};
    p.text((kLeft + kRight) / 2, kCurvePlotHeight - 16, l.generations ? "generation (log scale)" : "seconds (log scale)", axisLabel);
    axisLabel.vertical = true;
    p.text(20, (kTop + kBottom) / 2, "fitness", axisLabel);
    if (withIoU) {
        p.line(kRight, kTop, kRight, kBottom, kIoU);
        for (int k = 0; k <= 5; ++k) {
            const double v = k / 5.0, y = l.pIoU(v);
            p.line(kRight, y, kRight + 5, y, kIoU);
            p.text(kRight + 8, y + 4, tickLabel(v, 0.2), {kFont, TextAnchor::Start, false, false, kIoU});
        }
        axisLabel.colour = kIoU;
        p.text(kCurvePlotWidth - 22, (kTop + kBottom) / 2, labels.iouName + " of the best", axisLabel);
    }
    // title and legend
    p.text(kLeft, 26, fitted(p, labels.title, kCurvePlotWidth - kLeft - 10, 15), {15, TextAnchor::Start, true});
    double x = kLeft;
    const double y = 48;
    auto entry = [&](const std::string& text) {
        p.text(x + 28, y + 4, text, {kFont});
        x += 28 + p.textWidth(text, kFont, false) + 24;
    };
    p.line(x, y, x + 22, y, kBest, 2);
    entry("best fitness");
    p.rect(x, y - 6, 22, 12, kBand);
    p.line(x, y, x + 22, y, kMean, 1.5, true);
    entry("mean \u00b1 std of the population");
    if (withIoU) {
        p.line(x, y, x + 22, y, kIoU, 1.5);
        entry(labels.iouName + " of the best (right axis)");
    }
    if (l.best.empty() && l.mean.empty() && l.iou.empty())
        p.text((kLeft + kRight) / 2, (kTop + kBottom) / 2, "no data", {14, TextAnchor::Middle, false, false, kMuted});
}

}  // namespace

void writeCurveSvg(const std::vector<GenerationStats>& curve, const CurvePlotLabels& labels, const std::string& path) {
    SvgPainter svg(kCurvePlotWidth, kCurvePlotHeight, labels.title);
    draw(svg, layout(curve, labels.timeAxis), labels);
    const std::string text = svg.document();
    writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
}

void writeCurvePng(const std::vector<GenerationStats>& curve, const CurvePlotLabels& labels, const std::string& path) {
    CairoPainter png(kCurvePlotWidth, kCurvePlotHeight);
    draw(png, layout(curve, labels.timeAxis), labels);
    png.writePng(path);
}

}  // namespace shapevo
