// bench_search_methods: one whole run of each search method (GA, SMC, SOSMC, RJMCMC with and
// without delayed rejection) on configs/spaceship.toml (population 200, its generation count),
// one Evaluator thread. Each iteration is a fresh method with the config's seed, so every
// iteration does identical work. Reports wall time per run, evaluations per run and per second
// (the cost of a method's own bookkeeping shows as evals/s below the GA's), and the best fitness.
//
//   cd build && ninja bench_search_methods && ./bench/bench_search_methods --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cstdint>

#include "grammar/parser.hpp"
#include "run/config_file.hpp"
#include "score/volume_scorer.hpp"
#include "search/search_method.hpp"

namespace {

using namespace shapevo;

void BM_SearchRun(benchmark::State& state) {
    RunSettings s = loadConfig(SHAPEVO_SOURCE_DIR "/configs/spaceship.toml");
    s.search.method = SearchMethodKind(state.range(0) > 3 ? 3 : state.range(0));
    s.search.rjmcmc.delayedRejection = state.range(0) == 4;
    const Grammar grammar = loadGrammar(s.grammarPath);
    const VolumeTarget target = loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr);
    const VolumeScorer scorer(grammar, target, s.fitness);
    Evaluator evaluator(scorer, 1);
    std::uint64_t evaluations = 0;
    double best = 0;
    for (auto _ : state) {
        auto method = makeSearchMethod(s.search, s.ga, grammar, s.limits, s.seed);
        method->initialize(evaluator);
        while (method->generation() < s.ga.generations) method->step(evaluator);
        evaluations += method->evaluations();
        const GenerationStats stats = method->stats();
        benchmark::DoNotOptimize(&stats);
        best = stats.best;
    }
    state.counters["evals/s"] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
    state.counters["evals/run"] = benchmark::Counter(double(evaluations), benchmark::Counter::kAvgIterations);
    state.counters["best"] = best;
}

// 0 ga, 1 smc, 2 sosmc, 3 rjmcmc, 4 rjmcmc with delayed rejection
BENCHMARK(BM_SearchRun)->ArgName("method")->DenseRange(0, 4)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
