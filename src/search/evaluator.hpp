// Evaluator: scores a range of a population in parallel on a fixed number of TBB threads.
// Scoring is a pure function of each chromosome, so results never depend on the thread count.
#pragma once
#include <memory>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "score/scorer.hpp"
#include "search/population.hpp"

namespace shapevo {

class Evaluator {
public:
    /// threads = 0: all hardware threads.
    Evaluator(const Scorer& scorer, int threads);
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
