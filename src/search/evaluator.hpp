// Evaluator: scores a range of a population in parallel on a fixed number of TBB threads.
// Scoring is a pure function of each chromosome, so results never depend on the thread count.
// It never asks for more threads than the machine gives it, so threads() is what is used.
#pragma once
#include <memory>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "score/scorer.hpp"
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
    int threads() const { return arena_.max_concurrency(); }
    const Scorer& scorer() const { return scorer_; }

private:
    const Scorer& scorer_;
    tbb::task_arena arena_;
    tbb::enumerable_thread_specific<std::unique_ptr<ScoreWorkspace>> workspaces_;
};

}  // namespace shapevo
