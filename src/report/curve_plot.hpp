// Curve plot: a run's fitness curve as a self-contained SVG (real text) and as a PNG of the same
// layout, both drawn by the one function in curve_plot.cpp through a PlotPainter (cairo for the
// pixels). The page has a title, a legend, a logarithmic x axis ("seconds", or "generation")
// with ticks at 1, 2 and 5 of each decade, a "fitness" y axis with the best fitness (vermillion)
// and the mean with a ± one standard deviation band (blue), and, when rows carry an IoU, the
// best model's IoU (green) on a right-hand 0..1 axis. Points whose values are not finite are
// left out; times of 0 sit at the first positive time. Both files appear atomically.
#pragma once
#include <string>
#include <vector>

#include "search/generation_stats.hpp"

namespace shapevo {

/// Size of both plots in pixels (SVG user units).
inline constexpr int kCurvePlotWidth = 880, kCurvePlotHeight = 520;

enum class CurveTimeAxis { Seconds, Generations };

struct CurvePlotLabels {
    std::string title = "shapevo fitness curve";  ///< e.g. "tree-logo: targets/tree.png (...)"
    std::string iouName = "IoU";                  ///< right axis and legend, e.g. "silhouette IoU"
    /// Seconds (falls back to generations when no row has a positive finite time).
    CurveTimeAxis timeAxis = CurveTimeAxis::Seconds;
};

/// @throw InputError naming `path` if it cannot be written.
void writeCurveSvg(const std::vector<GenerationStats>& curve, const CurvePlotLabels& labels, const std::string& path);
/// @throw InputError naming `path` if it cannot be written.
void writeCurvePng(const std::vector<GenerationStats>& curve, const CurvePlotLabels& labels, const std::string& path);

}  // namespace shapevo
