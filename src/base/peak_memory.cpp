// peakResidentBytes: getrusage's ru_maxrss, which Linux gives in KiB.
#include "base/peak_memory.hpp"

#include <sys/resource.h>

namespace shapevo {

std::uint64_t peakResidentBytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return std::uint64_t(usage.ru_maxrss) * 1024;
}

}  // namespace shapevo
