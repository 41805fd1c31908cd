// bench_search_methods: one whole run of each search method of search/search_methods.hpp's table
// (argument i = the table's i-th method; one more argument runs RJMCMC with delayed rejection) on configs/spaceship.toml (population 200, its generation count),
// one Evaluator thread. Each iteration is a fresh method with the config's seed, so every
// iteration does identical work. Reports wall time per run, evaluations per run and per second
// (the cost of a method's own bookkeeping shows as evals/s below the GA's), and the best fitness.
//
//   cd build && ninja bench_search_methods && ./bench/bench_search_methods --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "score/volume/volume_kind.hpp"
#include "score/volume/volume_scorer.hpp"
#include "search/search_methods.hpp"

namespace {

using namespace shapevo;

void BM_SearchRun(benchmark::State& state) {
    RunSettings s = loadConfig(SHAPEVO_SOURCE_DIR "/configs/spaceship.toml");
    const auto methods = searchMethods();
    const auto i = std::size_t(state.range(0));
    s.search.method = i < methods.size() ? methods[i].name : "rjmcmc";
    s.search.rjmcmc.delayedRejection = i == methods.size();
    state.SetLabel(std::string(s.search.method) + (s.search.rjmcmc.delayedRejection ? " +DR" : ""));
    const Grammar grammar = loadGrammar(s.grammarPath);
    const TreeFamily family(grammar);
    const auto& volume = static_cast<const VolumeTargetSettings&>(*s.target);  // spaceship.toml is a volume config
    const VolumeTarget target = loadVolumeTarget(volume.targets, volume.grid ? &*volume.grid : nullptr);
    const VolumeScorer scorer(grammar, target, s.fitness);
    Evaluator evaluator(scorer, 1);
    std::uint64_t evaluations = 0;
    double best = 0;
    for (auto _ : state) {
        auto method = makeSearchMethod(s.search, s.population, s.ga, family, s.limits, s.seed, s.configPath);
        method->initialize(evaluator);
        while (method->generation() < s.population.generations) method->step(evaluator);
        evaluations += method->evaluations();
        const GenerationStats stats = method->stats();
        benchmark::DoNotOptimize(&stats);
        best = stats.best;
    }
    state.counters["evals/s"] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
    state.counters["evals/run"] = benchmark::Counter(double(evaluations), benchmark::Counter::kAvgIterations);
    state.counters["best"] = best;
}

// every method of the table, then RJMCMC with delayed rejection
BENCHMARK(BM_SearchRun)->ArgName("method")->DenseRange(0, int(searchMethods().size()))->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
