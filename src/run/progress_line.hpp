// ProgressLine: rank 0's line per generation: every one of the first 20 generations, then at
// most one a second, and always the last one, so hour-long runs stay readable. Besides the
// search's figures it shows the islands' waiting (mean and slowest share of wall time) and, in
// async mode, how old the newest figures from the other islands are.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

#include "search/generation_stats.hpp"

namespace shapevo {

/// "12.34s", "5m07s", "2h03m".
std::string humanSeconds(double seconds);

struct ProgressFigures {
    GenerationStats row;              ///< the run's figures (over every island)
    double runSecondsBefore = 0;      ///< wall time of earlier sessions (resume)
    double waitShareMean = 0, waitShareMax = 0;
    int islands = 1, islandsHeard = 1;
    double oldestAgeSeconds = -1;     ///< async: age of the oldest island figures used (-1: none)
};

class ProgressLine {
public:
    /// `generations`: the run's limit (kNoGenerationLimit: its wall time alone, "gen 12" without a
    /// total); `wallTime`: 0 = none.
    ProgressLine(std::ostream& log, std::uint32_t generations, double wallTime);
    /// Whether a line for `generation` is due (`last`: the run stops after it).
    bool due(std::uint32_t generation, bool last) const;
    void print(const ProgressFigures& f);

private:
    std::ostream& log_;
    std::uint32_t generations_;
    double wallTime_;
    double lastPrint_ = -1e300;
};

}  // namespace shapevo
