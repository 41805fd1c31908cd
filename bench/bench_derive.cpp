// bench_derive: throughput of derive() (chromosome -> primitives), the first half of every
// fitness evaluation. Spaceship chromosomes of ~20, ~50 and 100 genes and coral chromosomes of
// 100 and 1000 genes, each grown with a fixed seed, and a 50,000-gene tree.grammar chromosome (a
// full ternary tree built breadth first); castle.grammar and building.grammar (a street)
// chromosomes for the building statements; one DeriveScratch and one Geometry reused.
// items_per_second = derivations/s; "primitives/s" = primitives emitted per second.
//
//   cd build && ninja bench_derive && taskset -c 1 ./bench/bench_derive --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

#include "breadth_first_tree.hpp"

#include "run_derive.hpp"

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

const Grammar& tree() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/tree.grammar");
    return g;
}

/// A full ternary tree.grammar chromosome of `genes` genes, built breadth first (child k of every
/// branch is the k-th instance of Branch), parameters drawn from the priors with a fixed seed.
Chromosome fullTree(std::uint32_t genes) {
    const Grammar& g = tree();
    std::vector<std::uint16_t> branches;
    for (const char* name : {"Branch(0, 120)", "Branch(120, 240)", "Branch(240, 360)"}) {
        const int r = g.findRule(name);
        if (r < 0) throw std::runtime_error(std::string("tree.grammar has no rule ") + name);
        branches.push_back(std::uint16_t(r));
    }
    return bench::breadthFirstTree(g, genes, {branches[0], branches[1], branches[2]});
}

const Grammar& castle() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/castle.grammar");
    return g;
}
const Grammar& street() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/building.grammar");
    return g;
}

using bench::runDerive;

void BM_DeriveSpaceship(benchmark::State& state) {
    runDerive(state, spaceship(), grown(spaceship(), std::uint32_t(state.range(0)), 42));
}
void BM_DeriveCoral(benchmark::State& state) { runDerive(state, coral(), grown(coral(), std::uint32_t(state.range(0)), 42)); }
void BM_DeriveTree(benchmark::State& state) { runDerive(state, tree(), fullTree(std::uint32_t(state.range(0)))); }

/// The building statements: castles (lots, edges, corners, comp, repeat, inline calls, colours)
/// and streets with windows (facades split into floors and tiles: many primitives per gene).
void BM_DeriveCastle(benchmark::State& state) { runDerive(state, castle(), grown(castle(), std::uint32_t(state.range(0)), 42)); }
void BM_DeriveStreet(benchmark::State& state) { runDerive(state, street(), grown(street(), std::uint32_t(state.range(0)), 42)); }

BENCHMARK(BM_DeriveCastle)->ArgName("genes")->Arg(4);
BENCHMARK(BM_DeriveStreet)->ArgName("genes")->Arg(12);
BENCHMARK(BM_DeriveSpaceship)->ArgName("genes")->Arg(20)->Arg(50)->Arg(100);
BENCHMARK(BM_DeriveCoral)->ArgName("genes")->Arg(100)->Arg(1000);
BENCHMARK(BM_DeriveTree)->ArgName("genes")->Arg(50000);

}  // namespace

BENCHMARK_MAIN();
