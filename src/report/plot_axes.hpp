// Plot axes: "nice" axis ranges and tick values (steps of 1, 2 or 5 times a power of ten) and
// the mapping from data values to pixel positions, shared by the SVG and PNG curve plots.
#pragma once
#include <string>
#include <vector>

namespace shapevo {

struct PlotAxis {
    double lo = 0, hi = 1;      ///< the drawn range (tick-aligned, lo < hi)
    double step = 1;            ///< distance between ticks
    std::vector<double> ticks;  ///< lo, lo + step, ..., hi
    /// Position of `v` between pixel coordinates `from` (at lo) and `to` (at hi).
    double map(double v, double from, double to) const { return from + (v - lo) / (hi - lo) * (to - from); }
};

/// An axis covering [min, max] with about `ticks` ticks; `integer` forces whole-number steps.
/// A single value gives a range around it; an empty range (min > max), non-finite ends or a
/// range too wide for a double fall back to [0, 1].
PlotAxis niceAxis(double min, double max, int ticks, bool integer);

/// A tick value as printed on the axis: as many decimals as the step needs (%g for extreme values).
std::string tickLabel(double value, double step);

}  // namespace shapevo
