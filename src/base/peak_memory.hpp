// peakResidentBytes: the most memory this process has held in RAM so far (its peak resident set,
// getrusage), for summary.json and the memory tables. 0 where the system does not say.
#pragma once
#include <cstdint>

namespace shapevo {

std::uint64_t peakResidentBytes();

}  // namespace shapevo
