// Evaluator: scores a range of a population in parallel on a fixed number of TBB threads.
// Scoring is a pure function of each chromosome, so results never depend on the thread count.
// It never asks for more threads than the machine gives it, so threads() is what is used.
// With incremental scoring on (Scorer::cacheBytes() > 0), a chromosome equal to one scored
// recently, or to an earlier one of the same batch, is not scored again: it takes that fitness
// (search/fitness_memo.hpp: four times the first batch's models, 256 to 4,096, in at most a
// quarter of score.cache_mb; exact, and the same with any thread count).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "score/scorer.hpp"
#include "search/fitness_memo.hpp"
#include "search/population.hpp"

namespace shapevo {

class Evaluator {
public:
    /// threads = 0: all hardware threads; more than there are: all of them (usableThreads).
    Evaluator(const Scorer& scorer, int threads);
    /// The threads an Evaluator asked for `requested` runs on: all the hardware threads this
    /// process may use (TBB's default concurrency, which respects CPU affinity) for 0 or more
    /// than those, `requested` otherwise. threads() reports the same number.
    static int usableThreads(int requested);
    /// Fill pop.fitness[i] for i in [from, pop.size()).
    void evaluate(Population& pop, std::size_t from = 0);
    /// Call `f(pop, from)` at the start of every evaluate(), before anything is scored (a
    /// benchmark records the children a search method makes, lineage and all).
    void observeBatches(std::function<void(const Population&, std::size_t)> f) { observer_ = std::move(f); }
    int threads() const { return arena_.max_concurrency(); }
    const Scorer& scorer() const { return scorer_; }
    /// Models that took a remembered fitness instead of being scored (since construction).
    std::uint64_t reused() const { return reused_; }
    /// Models scored from their parent's evaluation (genome Lineage; score/image/image_model.hpp), since construction.
    std::uint64_t scoredFromParent() const {
        std::uint64_t n = 0;
        for (const auto& ws : workspaces_)
            if (ws) n += ws->fromParent;
        return n;
    }
    /// Memory incremental scoring uses now: every thread's primitive cache (the part written so
    /// far) and the duplicate memo.
    std::size_t cacheBytesUsed() const {
        std::size_t bytes = memo_ ? memo_->bytesHeld() : 0;
        for (const auto& ws : workspaces_)
            if (ws) bytes += ws->cacheBytesUsed();
        return bytes;
    }

private:
    static constexpr std::size_t kMemoEntries = 4096;  ///< most models remembered
    const Scorer& scorer_;
    tbb::task_arena arena_;
    tbb::enumerable_thread_specific<std::unique_ptr<ScoreWorkspace>> workspaces_;
    std::optional<FitnessMemo> memo_;
    std::uint64_t reused_ = 0;
    std::function<void(const Population&, std::size_t)> observer_;
    // per batch (kept for their capacity): the indices to score, and for each index of the batch
    // the index it duplicates (-1: none), the memo entry it filled, its derive status
    std::vector<std::size_t> todo_;
    std::vector<std::int64_t> sameAs_;
    std::vector<FitnessMemo::Entry*> entry_;
    std::vector<DeriveStatus> status_;
};

}  // namespace shapevo
