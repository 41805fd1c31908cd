// ProgressLine: formatting and cadence of rank 0's progress line.
#include "run/progress_line.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "search/population_settings.hpp"

namespace shapevo {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

std::string humanSeconds(double s) {
    char b[32];
    if (s < 100) std::snprintf(b, sizeof b, "%.2fs", s);
    else if (s < 6000) std::snprintf(b, sizeof b, "%dm%02ds", int(s) / 60, int(s) % 60);
    else std::snprintf(b, sizeof b, "%dh%02dm", int(s) / 3600, int(s) / 60 % 60);
    return b;
}

ProgressLine::ProgressLine(std::ostream& log, std::uint32_t generations, double wallTime)
    : log_(log), generations_(generations), wallTime_(wallTime) {}

bool ProgressLine::due(std::uint32_t generation, bool last) const {
    return generation <= 20 || last || now() - lastPrint_ >= 1.0;
}

void ProgressLine::print(const ProgressFigures& f) {
    lastPrint_ = now();
    const GenerationStats& g = f.row;
    const double rate = g.seconds > f.runSecondsBefore ? double(g.evaluations) / g.seconds : 0;
    const double perGeneration = g.seconds / std::max(1u, g.generation);
    const bool counted = generations_ != kNoGenerationLimit;  // else the wall time alone ends the run
    double eta = counted ? perGeneration * double(generations_ > g.generation ? generations_ - g.generation : 0) : 1e300;
    if (wallTime_ > 0) eta = std::min(eta, std::max(0.0, wallTime_ - g.seconds));
    char line[320];
    int n = counted ? std::snprintf(line, sizeof line, "gen %*u/%u", int(std::to_string(generations_).size()), g.generation, generations_)
                    : std::snprintf(line, sizeof line, "gen %u", g.generation);
    n += std::snprintf(line + n, sizeof line - std::size_t(n), "  best %.5f  IoU %.4f  mean %.5f  %.0f evals/s", g.best, g.iou,
                       g.mean, rate);
    if (f.islands > 1)
        n += std::snprintf(line + n, sizeof line - std::size_t(n), "  wait %.1f%% (max %.1f%%)", 100 * f.waitShareMean,
                           100 * f.waitShareMax);
    n += std::snprintf(line + n, sizeof line - std::size_t(n), "  elapsed %s  ETA %s", humanSeconds(g.seconds).c_str(),
                       humanSeconds(eta).c_str());
    if (f.oldestAgeSeconds >= 0)
        n += std::snprintf(line + n, sizeof line - std::size_t(n), "  [%d/%d islands, oldest figures %.1fs]",
                           f.islandsHeard, f.islands, f.oldestAgeSeconds);
    log_ << line << '\n' << std::flush;
}

}  // namespace shapevo
