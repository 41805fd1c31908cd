// RunLimit: what ends a run when no signal and no target fitness does: a number of generations
// (ga.generations), a wall time (run.wall_time), or both, whichever comes first. A wall time
// given without a generation count runs for that time (no generation limit); neither given: the
// default generation count (PopulationSettings). The run's start-up line names the limit.
#pragma once
#include <string>

#include "run/settings.hpp"

namespace shapevo {

/// Set s.population.generations from what was given: the generation count when one was
/// (s.generationsGiven), none (kNoGenerationLimit) for a wall time alone, else the default.
/// Called once every source (config, --set, resume's options) has set wallTime and generations.
void settleRunLimit(RunSettings& s);

/// "limit: 60 s wall time", "limit: 50 generations" or "limit: 50 generations or 60 s,
/// whichever comes first", for the start-up line.
std::string runLimitText(const RunSettings& s);

}  // namespace shapevo
