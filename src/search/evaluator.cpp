// Evaluator: TBB parallel_for inside a task_arena limited to the configured thread count.
#include "search/evaluator.hpp"

#include <algorithm>

#include <tbb/info.h>
#include <tbb/parallel_for.h>

namespace shapevo {

int Evaluator::usableThreads(int requested) {
    const int available = std::max(1, tbb::info::default_concurrency());
    return requested > 0 && requested < available ? requested : available;
}

Evaluator::Evaluator(const Scorer& scorer, int threads) : scorer_(scorer), arena_(usableThreads(threads)) {}

namespace {
/// Ask for every cache line of `c`'s words (a batch's chromosomes were written a while ago).
void prefetchWords(const Chromosome& c) {
    const char* const first = reinterpret_cast<const char*>(c.words.data());
    const std::size_t bytes = c.words.size() * sizeof(std::uint32_t);
    for (std::size_t at = 0; at < bytes; at += 64) __builtin_prefetch(first + at);
}
}  // namespace

void Evaluator::evaluate(Population& pop, std::size_t from) {
    if (observer_) observer_(pop, from);
    const std::size_t n = pop.size();
    pop.fitness.resize(n);
    // Which to score: on one thread, in population order (so the same with any thread count).
    todo_.clear();
    if (!memo_ && scorer_.cacheBytes() > 0)  // four batches' worth (a few generations), known now
        memo_.emplace(std::clamp<std::size_t>(4 * (n - from), kMemoEntries / 16, kMemoEntries), scorer_.cacheBytes() / 4);
    if (memo_) {
        sameAs_.assign(n, -1);
        entry_.assign(n, nullptr);
        status_.resize(n);
        for (std::size_t i = from; i < n; ++i) {
            const Chromosome& c = pop.individuals[i];
            if (i + 1 < n) prefetchWords(pop.individuals[i + 1]);  // hashed next: on its way meanwhile
            const std::uint64_t h = FitnessMemo::hashOf(c);
            if (FitnessMemo::Entry* e = memo_->find(c, h)) {
                if (e->pending >= 0) {
                    sameAs_[i] = e->pending;  // an earlier one of this batch: known after scoring
                } else {
                    pop.fitness[i] = e->fitness;
                    scorer_.countAgain(e->status);
                    pop.individuals[i].lineage = Lineage{e->model.lock()};  // (null once no model holds it)
                }
                ++reused_;
                continue;
            }
            if (FitnessMemo::Entry* e = memo_->insert(c, h)) {
                e->pending = std::int64_t(i);
                entry_[i] = e;
            }
            todo_.push_back(i);
        }
    } else {
        for (std::size_t i = from; i < n; ++i) todo_.push_back(i);
    }
    arena_.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo_.size(), 4), [&](const tbb::blocked_range<std::size_t>& r) {
            auto& ws = workspaces_.local();
            if (!ws) ws = scorer_.makeWorkspace();
            for (std::size_t k = r.begin(); k != r.end(); ++k) {
                const std::size_t i = todo_[k];
                if (k + 1 != r.end()) scorer_.prepare(pop.individuals[todo_[k + 1]]);
                pop.fitness[i] = scorer_.fitness(pop.individuals[i], *ws);
                // What scoring left for its children (or nothing): its lineage from now on.
                pop.individuals[i].lineage = Lineage{std::move(ws->made)};
                if (memo_) status_[i] = ws->status;
            }
        });
    });
    if (!memo_) return;
    for (std::size_t i : todo_) {
        FitnessMemo::Entry* e = entry_[i];
        if (!e || e->pending != std::int64_t(i)) continue;  // not remembered, or replaced within the batch
        e->fitness = pop.fitness[i];
        e->status = status_[i];
        e->pending = -1;
        e->model = pop.individuals[i].lineage.parent;
    }
    for (std::size_t i = from; i < n; ++i)
        if (sameAs_[i] >= 0) {
            pop.fitness[i] = pop.fitness[std::size_t(sameAs_[i])];
            pop.individuals[i].lineage = pop.individuals[std::size_t(sameAs_[i])].lineage;
            scorer_.countAgain(status_[std::size_t(sameAs_[i])]);
        }
}

}  // namespace shapevo
