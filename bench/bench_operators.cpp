// bench_operators: cost of the genetic operators (grow, cut, alter, crossover) on spaceship
// chromosomes of ~40 genes. Sixteen chromosomes are prepared with fixed seeds and used round-robin;
// grow / cut / alter first copy the prepared chromosome into a reused buffer (so the copy is part
// of the time — BM_Copy measures the bare copy, subtract it); crossover reads its parents as
// const and writes two reused children. items_per_second = operations/s.
//
//   cd build && ninja bench_operators && taskset -c 1 ./bench/bench_operators --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"

namespace {

using namespace shapevo;

constexpr std::uint32_t kGenes = 40;
constexpr std::size_t kPool = 16;  // power of two: round-robin with a mask
const GenomeLimits kLimits{100};   // as configs/spaceship.toml

const Grammar& spaceship() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/spaceship.grammar");
    return g;
}

const std::vector<Chromosome>& pool() {
    static const std::vector<Chromosome> p = [] {
        std::vector<Chromosome> v(kPool);
        for (std::size_t i = 0; i < kPool; ++i) {
            Rng rng(1000 + i);
            while (v[i].genes < kGenes && grow(spaceship(), v[i], rng, kLimits)) {
            }
        }
        return v;
    }();
    return p;
}

/// A buffer with capacity for any pool member (and room to grow), so copies never allocate.
Chromosome reusedBuffer() {
    Chromosome c;
    c.words.reserve(8192);
    return c;
}

void BM_Copy(benchmark::State& state) {
    const auto& p = pool();
    Chromosome buf = reusedBuffer();
    std::size_t i = 0;
    for (auto _ : state) {
        buf = p[i++ & (kPool - 1)];
        benchmark::DoNotOptimize(buf.words.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations());
}

/// Time one in-place mutation on a fresh copy of a pool chromosome per iteration (the copy is
/// included; BM_Copy measures it alone).
template <class Mutation>
void runMutation(benchmark::State& state, Mutation&& mutate) {
    const auto& p = pool();
    Chromosome buf = reusedBuffer();
    std::size_t i = 0, failed = 0;
    for (auto _ : state) {
        buf = p[i++ & (kPool - 1)];
        const bool ok = mutate(buf);
        benchmark::DoNotOptimize(ok);
        benchmark::DoNotOptimize(buf.words.data());
        failed += !ok;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["failed"] = benchmark::Counter(double(failed), benchmark::Counter::kAvgIterations);
}

void BM_Grow(benchmark::State& state) {
    Rng rng(7);
    runMutation(state, [&](Chromosome& c) { return grow(spaceship(), c, rng, kLimits); });
}

void BM_Cut(benchmark::State& state) {
    GenomeScratch scratch;
    scratch.newPos.reserve(8192);
    Rng rng(7);
    runMutation(state, [&](Chromosome& c) { return cut(spaceship(), c, rng, scratch); });
}

void BM_Alter(benchmark::State& state) {
    Rng rng(7);
    runMutation(state, [&](Chromosome& c) { return alter(spaceship(), c, rng); });
}

void BM_Crossover(benchmark::State& state) {
    const Grammar& g = spaceship();
    const auto& p = pool();
    Chromosome childA = reusedBuffer(), childB = reusedBuffer();
    GenomeScratch scratch;
    scratch.newPos.reserve(8192);
    Rng rng(7);
    std::size_t i = 0, failed = 0;
    for (auto _ : state) {
        const Chromosome& a = p[i & (kPool - 1)];
        const Chromosome& b = p[(i * 7 + 3) & (kPool - 1)];  // a different partner each time
        ++i;
        const bool ok = crossover(g, a, b, childA, childB, rng, kLimits, 3, scratch);
        benchmark::DoNotOptimize(ok);
        benchmark::DoNotOptimize(childA.words.data());
        benchmark::DoNotOptimize(childB.words.data());
        failed += !ok;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["failed"] = benchmark::Counter(double(failed), benchmark::Counter::kAvgIterations);
}

BENCHMARK(BM_Copy);
BENCHMARK(BM_Grow);
BENCHMARK(BM_Cut);
BENCHMARK(BM_Alter);
BENCHMARK(BM_Crossover);

}  // namespace

BENCHMARK_MAIN();
