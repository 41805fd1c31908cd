// Scorer: the one interface search methods see: chromosome -> fitness, a pure function.
// Volume (score/volume/volume_scorer.hpp) and image (score/image/image_scorer.hpp) targets implement it
// for derivation trees (through score/tree_scorer.hpp), score/image/drawing_scorer.hpp for drawings;
// each thread brings its own workspace, made by the scorer that uses it. A model whose
// derivation makes a non-finite or absurd number (geometry/derive.hpp) gets kWorstFitness; one
// that reaches the primitive limit is scored as it stands (its first maxPrimitives primitives).
// Both are counted (anomalies()), so a run can report them; the counts are sums over
// evaluations, the same whatever the thread count.
// Incremental scoring (setIncremental): a child is mostly its parent, so most of its primitives
// are bit-identical to primitives scored before; their rows are replayed from a per-thread cache
// (score/primitive_cache.hpp) instead of drawn again, and every gene's subtree derived before is
// copied from a per-thread memo (geometry/subtree_memo.hpp) instead of derived again. Fitness and
// counts stay bit-identical.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>

#include "genome/chromosome.hpp"
#include "geometry/derive.hpp"

namespace shapevo {

/// Per-thread scratch space of a scorer. A scorer's fitness() only ever receives the workspaces
/// its own makeWorkspace() made, so it may static_cast to its derived type.
struct ScoreWorkspace {
    virtual ~ScoreWorkspace() = default;
    DeriveStatus status = DeriveStatus::Complete;  ///< how the last model scored here derived
    /// Bytes its incremental-scoring cache and subtree memo have written so far (0 without them).
    virtual std::size_t cacheBytesUsed() const { return derive.memo ? derive.memo->bytesUsed() : 0; }
    DeriveScratch derive;
    Geometry geometry;
    /// Derivations with the memo so far, and of the sampled ones the seconds with and without it
    /// (TreeScorer::deriveCounted's trial: the memo stays on only where it is faster).
    std::uint32_t memoTrial = 0;
    double memoSeconds = 0, plainSeconds = 0;
    DeriveScratch checkDerive;  ///< the checking mode's (and the trial's) derivation without the memo...
    Geometry checkGeometry;     ///< ...and its geometry
    /// What the last fitness() left for the model's children (Lineage::parent; null: nothing):
    /// the Evaluator moves it into the model's lineage.
    std::shared_ptr<const EvaluatedModel> made;
    /// Models scored from their parent (Lineage), and those whose lineage named a change but
    /// were scored the other way (a parent truncated, a subtree past the limits).
    std::uint64_t fromParent = 0, notFromParent = 0;
};

/// Of an incremental-scoring budget of `bytes` (score.cache_mb), the subtree memo's share (a
/// quarter; geometry/subtree_memo.hpp). The image scorer gives another quarter to whole subtrees'
/// words and the rest to its primitive cache; the volume scorer has no memo.
inline std::size_t subtreeMemoBytes(std::size_t bytes) { return bytes / 4; }

/// The checking mode of incremental scoring found a model whose counts differ between the
/// incremental and the full evaluation (what() names both).
struct IncrementalMismatch : std::logic_error {
    using std::logic_error::logic_error;
};

class Scorer {
public:
    /// The fitness of a model with a non-finite or absurd coordinate: below every real fitness.
    static constexpr double kWorstFitness = -1e30;

    struct Anomalies {
        std::uint64_t nonFinite = 0;  ///< evaluations whose model had a non-finite or absurd number
        std::uint64_t truncated = 0;  ///< evaluations whose derivation reached the primitive limit
    };

    Scorer() = default;
    Scorer(const Scorer&) = delete;
    Scorer& operator=(const Scorer&) = delete;
    virtual ~Scorer() = default;
    virtual std::unique_ptr<ScoreWorkspace> makeWorkspace() const = 0;
    /// A workspace without an incremental-scoring cache, for scoring a model now and then (the
    /// progress line's IoU): the same results, none of the cache's memory.
    virtual std::unique_ptr<ScoreWorkspace> makePlainWorkspace() const { return makeWorkspace(); }
    /// Higher is better. Must not allocate once the workspace is warm.
    virtual double fitness(const Chromosome& c, ScoreWorkspace& w) const = 0;
    /// A hint that `c` is scored next on this thread: bring what it will read towards the
    /// processor's cache (no result depends on it).
    virtual void prepare(const Chromosome& c) const { (void)c; }

    /// Incremental scoring (score.incremental, score.cache_mb): each workspace made from now on
    /// keeps the rows its primitives drew in a PrimitiveCache of about `bytes` (0: off, every
    /// primitive is drawn anew). With `check`, every model is also scored the full way and a
    /// difference throws IncrementalMismatch. Results never depend on it: only the time does.
    virtual void setIncremental(std::size_t bytes, bool check = false) {
        cacheBytes_ = bytes;
        checkIncremental_ = check && bytes > 0;
    }
    std::size_t cacheBytes() const { return cacheBytes_; }
    /// Some workspace's cache reached cacheBytes() and would have grown (PrimitiveCache::full):
    /// from then on part of the models are drawn the full way. A run says so once.
    bool cacheFull() const { return cacheFull_.load(std::memory_order_relaxed); }
    bool checksIncremental() const { return checkIncremental_; }
    /// Some model's state for its children (scoring from the parent) was not kept because the
    /// models of this scorer reached score.cache_mb: its children are scored from the caches
    /// instead. A run says so once.
    virtual bool modelsFull() const { return false; }
    /// Bytes the models of this scorer keep now for their children (0 where it keeps none).
    virtual std::size_t modelBytesInUse() const { return 0; }

    /// genome.max_primitives: derivation stops (Truncated) after this many primitives.
    void setMaxPrimitives(std::size_t n) { maxPrimitives_ = n; }
    std::size_t maxPrimitives() const { return maxPrimitives_; }
    Anomalies anomalies() const { return {nonFinite_.load(), truncated_.load()}; }
    /// Count the anomaly of a model that is not scored again (a duplicate of one scored with
    /// `status`), so that anomalies() stay the sums over every evaluation.
    void countAgain(DeriveStatus status) const { countAnomaly(status); }

protected:
    void noteCacheFull() const {
        if (!cacheFull_.load(std::memory_order_relaxed)) cacheFull_.store(true, std::memory_order_relaxed);
    }
    /// Whether a model of `primitives` primitives goes through the workspace's primitive cache:
    /// there is one and it holds the model (PrimitiveCache::holds). A model larger than it is
    /// drawn the full way, and the cache counts as full (said once by the run).
    template <class Cache>
    bool throughCache(const std::optional<Cache>& cache, std::size_t primitives) const {
        if (!cache) return false;
        if (cache->holds(primitives)) return true;
        noteCacheFull();
        return false;
    }
    /// Count a derivation's anomaly in anomalies() (Truncated, NonFinite; Complete counts nothing).
    void countAnomaly(DeriveStatus status) const {
        if (status == DeriveStatus::Truncated) truncated_.fetch_add(1, std::memory_order_relaxed);
        if (status == DeriveStatus::NonFinite) nonFinite_.fetch_add(1, std::memory_order_relaxed);
    }

private:
    std::size_t cacheBytes_ = 0;
    bool checkIncremental_ = false;
    mutable std::atomic<bool> cacheFull_{false};
    std::size_t maxPrimitives_ = kDefaultMaxPrimitives;
    mutable std::atomic<std::uint64_t> nonFinite_{0}, truncated_{0};
};

}  // namespace shapevo
