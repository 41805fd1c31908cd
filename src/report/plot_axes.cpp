// Plot axes: nice steps by rounding range/ticks up to 1, 2 or 5 times a power of ten.
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
