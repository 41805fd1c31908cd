// bench_crl: CastleMaker rule files through shapevo. (1) derive speed of a CRL file against a
// .grammar file of the same structure: grammars/castlemaker/toy-castle.rule and its hand-written
// twin bench/data/toy-castle.grammar (same kinds and counts of primitives); compare ns per
// derivation and per primitive (both are one gene). (2) The toy skyscrapers of §7.3 (nine rules,
// ~1.6 M triangles): derive, and tessellate + write as GLB; "triangles/s" is the rate.
//
//   cd build && ninja bench_crl && taskset -c 1 ./bench/bench_crl --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "genome/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "geometry/tessellation.hpp"
#include "grammar/front_ends.hpp"
#include "mesh/glb_writer.hpp"

#include "run_derive.hpp"

namespace {

using namespace shapevo;

const Grammar& load(const char* relative) {
    static std::map<std::string, Grammar> cache;
    auto it = cache.find(relative);
    if (it == cache.end()) it = cache.emplace(relative, loadGrammar(std::string(SHAPEVO_SOURCE_DIR "/") + relative)).first;
    return it->second;
}

/// An uncontrolled derivation with a fixed seed whose door is the 7 x 5 one (202 primitives in
/// both castles), so both benchmarks derive the same model structure.
Chromosome castleSample(const Grammar& g) {
    DeriveScratch scratch;
    Geometry geo;
    for (std::uint64_t seed = 1;; ++seed) {
        Rng rng(seed);
        Chromosome c;
        if (!growUncontrolled(g, c, rng, 100)) continue;
        derive(g, c, geo, scratch);
        if (geo.primitives.size() == 202) return c;
    }
}

using bench::runDerive;

void BM_DeriveToyCastleRule(benchmark::State& state) {
    const Grammar& g = load("grammars/castlemaker/toy-castle.rule");
    runDerive(state, g, castleSample(g));
}
void BM_DeriveToyCastleGrammar(benchmark::State& state) {
    const Grammar& g = load("bench/data/toy-castle.grammar");
    runDerive(state, g, castleSample(g));
}

Chromosome skyscrapers() {
    const Grammar& g = load("grammars/castlemaker/toy-skyscrapers.rule");
    Rng rng(1);
    Chromosome c;
    growUncontrolled(g, c, rng, 10);
    return c;
}

void BM_DeriveToySkyscrapers(benchmark::State& state) {
    const Grammar& g = load("grammars/castlemaker/toy-skyscrapers.rule");
    runDerive(state, g, skyscrapers());
    state.counters["triangles/s"] = benchmark::Counter(state.counters["primitives/s"].value * 12, benchmark::Counter::kIsRate);
}

void BM_WriteToySkyscrapersGlb(benchmark::State& state) {
    const Grammar& g = load("grammars/castlemaker/toy-skyscrapers.rule");
    const Chromosome c = skyscrapers();
    DeriveScratch scratch;
    Geometry geometry;
    const std::string path = (std::filesystem::temp_directory_path() / "bench_crl_skyscrapers.glb").string();
    std::size_t triangles = 0, bytes = 0;
    for (auto _ : state) {
        derive(g, c, geometry, scratch);
        const Mesh mesh = tessellate(geometry);
        writeGlb(mesh, path);
        triangles += mesh.triangles.size();
        bytes = std::filesystem::file_size(path);
    }
    std::filesystem::remove(path);
    state.SetItemsProcessed(state.iterations());
    state.counters["triangles"] = double(triangles / std::max<std::size_t>(1, state.iterations()));
    state.counters["triangles/s"] = benchmark::Counter(double(triangles), benchmark::Counter::kIsRate);
    state.counters["MB"] = double(bytes) / 1e6;
}

BENCHMARK(BM_DeriveToyCastleRule);
BENCHMARK(BM_DeriveToyCastleGrammar);
BENCHMARK(BM_DeriveToySkyscrapers)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteToySkyscrapersGlb)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
