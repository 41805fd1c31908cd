// Plot axes: nice steps by rounding range/ticks up to 1, 2 or 5 times a power of ten; log axes
// by walking the 1-2-5 ticks of each decade.
#include "report/plot_axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shapevo {

namespace {
double niceStep(double raw) {
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power * (1 + 1e-9)) return m * power;
    return 10.0 * power;
}
}  // namespace

PlotAxis niceAxis(double min, double max, int ticks, bool integer) {
    if (!std::isfinite(min) || !std::isfinite(max) || min > max || !std::isfinite(max - min)) min = 0, max = 1;
    if (min == max) {  // one value: centre it in a range of its own size (or 1)
        const double pad = std::max(integer ? 1.0 : 0.0, std::fabs(min) > 0 ? std::fabs(min) * 0.1 : 1.0);
        min -= pad, max += pad;
    }
    PlotAxis axis;
    axis.step = niceStep((max - min) / std::max(ticks, 1));
    if (integer) axis.step = std::max(axis.step, 1.0);
    const double first = std::floor(min / axis.step + 1e-9), last = std::ceil(max / axis.step - 1e-9);
    axis.lo = first * axis.step;
    axis.hi = std::max(last, first + 1) * axis.step;
    if (!(axis.hi > axis.lo)) {  // a tiny range at a huge magnitude (first + 1 == first): plain ends
        axis.lo = min, axis.hi = max, axis.step = max - min;
        axis.ticks = {min, max};
        return axis;
    }
    // a count, not a double loop: at huge magnitudes k + 1 == k
    const int count = int(std::clamp(last - first, 1.0, 1000.0));
    for (int i = 0; i <= count; ++i) axis.ticks.push_back(i == count ? axis.hi : (first + i) * axis.step);
    return axis;
}

double LogAxis::map(double v, double from, double to) const {
    return from + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (to - from);
}

namespace {
/// The 1-2-5 tick m * 10^e (m in {1, 2, 5}) as a double; index k = 3e + {0, 1, 2}.
double logTick(int k) {
    const int e = k >= 0 ? k / 3 : -((-k + 2) / 3);
    static constexpr double kMantissa[] = {1, 2, 5};
    return kMantissa[k - 3 * e] * std::pow(10.0, e);
}
/// Index of the largest tick <= v (v > 0, finite); with a tolerance, so 0.2 is its own tick.
int tickAtOrBelow(double v) {
    int k = 3 * int(std::floor(std::log10(v))) + 2;
    while (logTick(k) > v * (1 + 1e-9)) --k;
    return k;
}
}  // namespace

LogAxis logAxis(double min, double max) {
    if (!std::isfinite(min) || !std::isfinite(max) || !(min > 0) || min > max) min = 1, max = 10;
    min = std::clamp(min, 1e-300, 1e300), max = std::clamp(max, 1e-300, 1e300);
    LogAxis axis;
    const int first = tickAtOrBelow(min);
    int last = tickAtOrBelow(max);
    if (logTick(last) < max * (1 - 1e-9)) ++last;  // the smallest tick >= max
    if (last <= first) last = first + 1;
    axis.lo = logTick(first), axis.hi = logTick(last);
    const bool all = axis.hi / axis.lo <= 1000 * (1 + 1e-9);
    for (int k = first; k <= last; ++k) {
        axis.ticks.push_back(logTick(k));
        axis.labelled.push_back(all || k % 3 == 0 || k == first);
    }
    return axis;
}

std::string logTickLabel(double value) {
    char s[40];
    std::snprintf(s, sizeof s, "%g", value);
    return s;
}

std::string tickLabel(double value, double step) {
    if (std::fabs(value) < step * 1e-9) value = 0;  // no "-0" or "1e-17"
    char s[40];
    if (step >= 1e-4 && std::fabs(value) < 1e7) {
        // steps are 1, 2 or 5 times 10^k: exactly max(0, -k) decimals
        const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
        std::snprintf(s, sizeof s, "%.*f", decimals, value);
    } else {
        std::snprintf(s, sizeof s, "%.3g", value);
    }
    return s;
}

}  // namespace shapevo
