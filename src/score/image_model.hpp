// ImageModel: what scoring a model against an image target leaves for its children
// (genome/chromosome.hpp, Lineage::parent): its chromosome, its derivation's totals, its pixel
// counts and, made the first time a child asks, how many primitives cover each pixel. A child
// whose operator changed one subtree is then scored from it (ImageScorer::fromParent): only the
// changed subtree is derived and drawn, twice (as it was and as it is), whatever the model's size.
//
// Promises: immutable once made, except coverage(), which is made once (thread safe) and never
// changes after. Holds no lineage itself, so a model never keeps its ancestors alive.
#pragma once
#include <atomic>
#include <cstddef>
#include <mutex>

#include "genome/chromosome.hpp"
#include "score/coverage_counts.hpp"
#include "score/silhouette_raster.hpp"

namespace shapevo {

struct ImageModel final : EvaluatedModel {
    Chromosome chromosome;  ///< lineage empty
    std::size_t primitives = 0, tasks = 0;  ///< of its derivation, which was Complete
    SilhouetteCounts counts;

    /// The coverage counts, made by `make(CoverageCounts&)` on the first call.
    template <class Make>
    const CoverageCounts& coverage(Make&& make) const {
        if (!made_.load(std::memory_order_acquire)) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!made_.load(std::memory_order_relaxed)) {
                make(coverage_);
                made_.store(true, std::memory_order_release);
            }
        }
        return coverage_;
    }
    /// The coverage counts if made (null otherwise), for memory counts.
    const CoverageCounts* coverageIfMade() const { return made_.load(std::memory_order_acquire) ? &coverage_ : nullptr; }
    /// Give it coverage counts already made (before anyone else sees it).
    void setCoverage(CoverageCounts&& c) {
        coverage_ = std::move(c);
        made_.store(true, std::memory_order_relaxed);
    }

private:
    mutable std::mutex mutex_;
    mutable std::atomic<bool> made_{false};
    mutable CoverageCounts coverage_;
};

}  // namespace shapevo
