// IncrementalSettings: the [score] keys of incremental scoring (Scorer::setIncremental).
//   score.incremental       = true   replay the rows of primitives scored before (false: draw every one)
//   score.cache_mb          = 64     the cache's size per evaluation thread, in MiB; past it the
//                                    oldest primitives are forgotten and drawn again when they return
//   score.check_incremental = false  also score every model the full way; stop on any difference
#pragma once
#include <cstddef>

namespace shapevo {

struct IncrementalSettings {
    bool enabled = true;
    double cacheMb = 64;
    bool check = false;
    /// The cache bytes per thread that Scorer::setIncremental takes (0: off).
    std::size_t cacheBytes() const { return enabled ? std::size_t(cacheMb * 1024 * 1024) : 0; }
};

}  // namespace shapevo
