// bench_generation: one whole GA run with the settings of configs/spaceship.toml (population 200,
// generations from the config: initialize + generations-1 steps), on 1 and 2 Evaluator threads.
// Grammar, target, scorer and evaluator are built once; each iteration is a fresh
// GeneticAlgorithm with the config's seed, so every iteration does identical work.
// Reports wall time per run (UseRealTime) and evals/s.
//
//   cd build && ninja bench_generation && ./bench/bench_generation --benchmark_min_time=5
#include <benchmark/benchmark.h>

#include <cstdint>

#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "score/volume/volume_scorer.hpp"
#include "score/volume/volume_kind.hpp"
#include "search/genetic_algorithm.hpp"

namespace {

using namespace shapevo;

void BM_GaRun(benchmark::State& state) {
    const RunSettings s = loadConfig(SHAPEVO_SOURCE_DIR "/configs/spaceship.toml");
    const Grammar grammar = loadGrammar(s.grammarPath);
    const TreeFamily family(grammar);
    const auto& volume = static_cast<const VolumeTargetSettings&>(*s.target);  // spaceship.toml is a volume config
    const VolumeTarget target = loadVolumeTarget(volume.targets, volume.grid ? &*volume.grid : nullptr);
    const VolumeScorer scorer(grammar, target, s.fitness);
    Evaluator evaluator(scorer, int(state.range(0)));
    std::uint64_t evaluations = 0;
    double best = 0;
    for (auto _ : state) {
        GeneticAlgorithm ga(family, s.population, s.ga, s.limits, s.seed);
        ga.initialize(evaluator);
        while (ga.generation() < s.population.generations) ga.step(evaluator);
        evaluations += ga.evaluations();
        best = ga.population().fitness[ga.population().best()];
        benchmark::DoNotOptimize(best);
    }
    state.counters["evals/s"] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
    state.counters["evals/run"] = benchmark::Counter(double(evaluations), benchmark::Counter::kAvgIterations);
    state.counters["best"] = best;
    state.counters["eval_threads"] = double(evaluator.threads());
}

BENCHMARK(BM_GaRun)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
