// ImageModel: what scoring a model against an image target leaves for its children
// (genome/chromosome.hpp, Lineage::parent): its chromosome, its derivation's totals, its pixel
// counts and, made the first time a child asks, how many primitives cover each pixel. A child
// whose operator changed one subtree is then scored from it (ImageScorer::fromParent): only the
// changed subtree is derived and drawn, twice (as it was and as it is), whatever the model's size.
//
// Promises: immutable once made, except coverage(), which is made once (thread safe) and never
// changes after. Holds no lineage itself; a model scored from its parent holds that parent (not
// further ancestors: a parent's coverage is flat before a child overlays it) until its own
// coverage is first asked for. Models come
// from a ModelStore (score/image/model_store.hpp), which clears them for reuse when the last holder goes.
#pragma once
#include <atomic>
#include <cstddef>
#include <mutex>

#include "genome/chromosome.hpp"
#include "score/image/coverage_counts.hpp"
#include "score/image/silhouette_raster.hpp"

namespace shapevo {

struct ImageModel final : EvaluatedModel {
    Chromosome chromosome;  ///< lineage empty
    std::size_t primitives = 0, tasks = 0;  ///< of its derivation, which was Complete
    SilhouetteCounts counts;
    std::size_t countedBytes = 0;  ///< what its ModelStore counted for it

    /// The coverage counts, on the first call flattened from the overlay on its parent's (see
    /// setOverlay) or, without one, made by `make(CoverageCounts&)`.
    template <class Make>
    const CoverageCounts& coverage(Make&& make) const {
        if (!made_.load(std::memory_order_acquire)) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!made_.load(std::memory_order_relaxed)) {
                if (overlaid_) {
                    coverage_.flatten();  // a reference on each block it shares with the parent...
                    parent_.reset();      // ...so the parent may go
                } else {
                    make(coverage_);
                }
                made_.store(true, std::memory_order_release);
            }
        }
        return coverage_;
    }
    /// The coverage counts if made (null otherwise), for memory counts.
    const CoverageCounts* coverageIfMade() const { return made_.load(std::memory_order_acquire) ? &coverage_ : nullptr; }
    /// Whether coverage() costs no derivation: made, or an overlay on its parent's.
    bool coverageAtHand() const { return overlaid_ || made_.load(std::memory_order_acquire); }
    /// Give it coverage counts that are an overlay on its parent's (the ones `parent` made),
    /// before anyone else sees it: swapped with its own (cleared) ones, so `c` keeps their
    /// capacity. It holds the parent until its coverage is first asked for (then flattened), so
    /// a model that never has children never takes a reference on the parent's blocks.
    void setOverlay(CoverageCounts& c, std::shared_ptr<const EvaluatedModel> parent) {
        std::swap(coverage_, c);
        parent_ = std::move(parent);
        overlaid_ = true;
    }
    /// The blocks it holds itself (an overlay's own), for memory counts; quiet times only.
    template <class F>
    void forEachBlockHeld(F&& f) const {
        if (overlaid_ || made_.load(std::memory_order_acquire)) coverage_.forEachBlock(f);
    }
    /// Ask for its coverage's block handles, if made (a child reads them as it copies blocks).
    void prefetchCoverageHandles() const {
        if (made_.load(std::memory_order_acquire)) coverage_.prefetchHandles();
    }
    /// Bytes of its coverage's block handles (their capacity; the blocks are counted apart).
    std::size_t handleBytes() const { return coverage_.handleBytes(); }
    /// Empty again, keeping the capacity of its buffers (ModelStore, when its last holder goes).
    void clear() {
        chromosome.words.clear();
        chromosome.genes = 0;
        primitives = tasks = 0;
        counts = SilhouetteCounts{};
        coverage_.clear();
        parent_.reset();
        overlaid_ = false;
        made_.store(false, std::memory_order_relaxed);
    }

private:
    mutable std::mutex mutex_;
    mutable std::atomic<bool> made_{false};
    bool overlaid_ = false;  ///< set before anyone else sees it
    mutable std::shared_ptr<const EvaluatedModel> parent_;  ///< an overlay's base, until flattened
    mutable CoverageCounts coverage_;
};

}  // namespace shapevo
