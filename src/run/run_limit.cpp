// RunLimit: settling the run's limit and naming it (run_limit.hpp).
#include "run/run_limit.hpp"

#include "base/format_double.hpp"

namespace shapevo {

void settleRunLimit(RunSettings& s) {
    if (s.generationsGiven) return;
    s.population.generations = s.wallTime > 0 ? kNoGenerationLimit : PopulationSettings{}.generations;
}

std::string runLimitText(const RunSettings& s) {
    const std::string seconds = formatDouble(s.wallTime) + " s";
    if (s.population.generations == kNoGenerationLimit) return "limit: " + seconds + " wall time";
    const std::uint32_t n = s.population.generations;
    const std::string generations = std::to_string(n) + (n == 1 ? " generation" : " generations");
    if (s.wallTime <= 0) return "limit: " + generations;
    return "limit: " + generations + " or " + seconds + ", whichever comes first";
}

}  // namespace shapevo
