// bench_derive: throughput of derive() (chromosome -> primitives), the first half of every
// fitness evaluation. Spaceship chromosomes of ~20, ~50 and 100 genes and coral chromosomes of
// 100 and 1000 genes, each grown with a fixed seed; one DeriveScratch and one Geometry reused.
// items_per_second = derivations/s; "primitives/s" = primitives emitted per second.
//
//   cd build && ninja bench_derive && taskset -c 1 ./bench/bench_derive --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/parser.hpp"

namespace {

using namespace shapevo;

const Grammar& spaceship() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/spaceship.grammar");
    return g;
}
const Grammar& coral() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/coral.grammar");
    return g;
}

/// Grow a chromosome from empty with a fixed seed until it has `genes` genes (or cannot grow).
Chromosome grown(const Grammar& g, std::uint32_t genes, std::uint64_t seed) {
    Rng rng(seed);
    const GenomeLimits limits{genes};
    Chromosome c;
    while (c.genes < genes && grow(g, c, rng, limits)) {
    }
    return c;
}

void runDerive(benchmark::State& state, const Grammar& g) {
    const Chromosome c = grown(g, std::uint32_t(state.range(0)), 42);
    DeriveScratch scratch;
    Geometry geometry;
    derive(g, c, geometry, scratch);  // warm the buffers
    const std::size_t primitivesPerDerivation = geometry.primitives.size();
    std::uint64_t primitives = 0;
    for (auto _ : state) {
        derive(g, c, geometry, scratch);
        benchmark::DoNotOptimize(geometry.primitives.data());
        benchmark::ClobberMemory();
        primitives += geometry.primitives.size();
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["primitives/s"] = benchmark::Counter(double(primitives), benchmark::Counter::kIsRate);
    state.counters["genes"] = double(c.genes);
    state.counters["primitives"] = double(primitivesPerDerivation);
}

void BM_DeriveSpaceship(benchmark::State& state) { runDerive(state, spaceship()); }
void BM_DeriveCoral(benchmark::State& state) { runDerive(state, coral()); }

BENCHMARK(BM_DeriveSpaceship)->ArgName("genes")->Arg(20)->Arg(50)->Arg(100);
BENCHMARK(BM_DeriveCoral)->ArgName("genes")->Arg(100)->Arg(1000);

}  // namespace

BENCHMARK_MAIN();
