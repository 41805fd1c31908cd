// The [score] section: the fitness form and its weights (score/fitness_settings.hpp) and the keys
// of incremental scoring (score/incremental_settings.hpp), read by the score stage itself.
#pragma once
#include "base/section_reader.hpp"
#include "score/fitness_settings.hpp"
#include "score/incremental_settings.hpp"

namespace shapevo {

/// Read [score] into `fitness` and `incremental` (absent keys keep their defaults).
/// @throw InputError for a wrong value, or length_max not greater than length_optimal.
void readScoreSection(SectionReader& score, FitnessSettings& fitness, IncrementalSettings& incremental);

}  // namespace shapevo
