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

void Evaluator::evaluate(Population& pop, std::size_t from) {
    pop.fitness.resize(pop.size());
    arena_.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(from, pop.size(), 4), [&](const tbb::blocked_range<std::size_t>& r) {
            auto& ws = workspaces_.local();
            if (!ws) ws = scorer_.makeWorkspace();
            for (std::size_t i = r.begin(); i != r.end(); ++i) pop.fitness[i] = scorer_.fitness(pop.individuals[i], *ws);
        });
    });
}

}  // namespace shapevo
