// runDerive: the loop every derive benchmark shares. Derives `c` once to warm the buffers, then
// once per iteration with one DeriveScratch and one Geometry; items_per_second = derivations/s,
// "primitives/s" the primitives emitted per second, "genes" and "primitives" per derivation.
#pragma once
#include <benchmark/benchmark.h>

#include <cstdint>

#include "geometry/derive.hpp"

namespace shapevo::bench {

inline void runDerive(benchmark::State& state, const Grammar& g, const Chromosome& c) {
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

}  // namespace shapevo::bench
