// IncrementalSettings: the [score] keys of incremental scoring (Scorer::setIncremental).
//   score.incremental       = true   reuse subtrees and primitives derived and drawn before (false: derive and draw every one)
//   score.cache_mb          = 128    the caches' size per evaluation thread, in MiB (half for
//                                    primitives); past it the oldest are forgotten and drawn again.
//                                    Also the most an island's models may keep for their children
//                                    (score/image/model_store.hpp); past it the largest are not kept
//   score.check_incremental = false  also score every model the full way; stop on any difference
#pragma once
#include <cstddef>

namespace shapevo {

struct IncrementalSettings {
    bool enabled = true;
    double cacheMb = 128;
    bool check = false;
    /// The cache bytes per thread that Scorer::setIncremental takes (0: off).
    std::size_t cacheBytes() const { return enabled ? std::size_t(cacheMb * 1024 * 1024) : 0; }
};

}  // namespace shapevo
