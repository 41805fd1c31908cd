// Curve plot: a run's fitness curve (best, and mean with a ± one standard deviation band, per
// generation) as a self-contained SVG (axes, ticks, labels, legend) or as a PNG of the same
// layout (lines and numbers only). Best is drawn in vermillion, mean and its band in blue.
// Points whose values are not finite are left out. Both files appear atomically.
#pragma once
#include <string>
#include <vector>

#include "search/genetic_algorithm.hpp"

namespace shapevo {

/// Size of both plots in pixels (SVG user units).
inline constexpr int kCurvePlotWidth = 800, kCurvePlotHeight = 480;

/// @throw InputError naming `path` if it cannot be written.
void writeCurveSvg(const std::vector<GenerationStats>& curve, const std::string& path);
/// @throw InputError naming `path` if it cannot be written.
void writeCurvePng(const std::vector<GenerationStats>& curve, const std::string& path);

}  // namespace shapevo
