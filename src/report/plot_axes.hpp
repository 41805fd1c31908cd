// Plot axes: "nice" linear axis ranges and tick values (steps of 1, 2 or 5 times a power of ten),
// logarithmic axes with ticks at 1, 2 and 5 of each decade, and the mapping from data values to
// pixel positions, shared by the SVG and PNG curve plots.
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

/// A logarithmic axis: lo and hi are ticks (1, 2 or 5 times a power of ten), lo < hi.
struct LogAxis {
    double lo = 1, hi = 10;
    std::vector<double> ticks;     ///< every 1, 2 and 5 of each decade within [lo, hi]
    std::vector<bool> labelled;    ///< per tick: gets a number (all over at most 3 decades, else 1s only)
    /// Position of `v` (> 0) between pixel coordinates `from` (at lo) and `to` (at hi).
    double map(double v, double from, double to) const;
};

/// A log axis covering [min, max]: from the largest 1-2-5 tick <= min to the smallest >= max.
/// min == max gives the ticks either side; non-positive or non-finite ends, or min > max,
/// fall back to [1, 10]. Ends beyond 1e-300..1e300 are clamped to that range.
LogAxis logAxis(double min, double max);

/// A tick value as printed on the axis: as many decimals as the step needs (%g for extreme values).
std::string tickLabel(double value, double step);
/// A log-axis tick as printed: "0.05", "1", "200", "5000", "1e+05" (%g: at most 6 digits).
std::string logTickLabel(double value);

}  // namespace shapevo
