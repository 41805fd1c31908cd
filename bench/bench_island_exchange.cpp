// bench_island_exchange: what the islands' exchanges cost on this machine, for docs/performance.md, "Islands" (the log: docs/history/2026-12-performance-log.md, "Islands: scaling")
// and its model of 1,024 ranks. Run under mpirun (every rank runs every benchmark the same fixed
// number of times, so the collectives pair up; only rank 0 reports):
//
//   mpirun --oversubscribe --bind-to none -np 2 build/bench/bench_island_exchange
//
// - BM_BlockingAllreduce: one MPI_Allreduce of 4 doubles, what each generation paid three times
//   before sync islands met only every meeting interval;
// - BM_Meeting/rows: one sync meeting (island/island_meeting.hpp) carrying `rows` generations;
// - BM_SyncMigration: one sync ring exchange of 5 spaceship chromosomes (packed, validated);
// - BM_AsyncStatus: one async status post (rank 1) and collection (rank 0), never blocking.
// The ranks are in step (a barrier before each timed loop), so these are costs, not waiting.
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <cstdio>

#include "genome/families/tree_family.hpp"
#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "island/async_control.hpp"
#include "island/island_meeting.hpp"
#include "island/ring_migration.hpp"

namespace {

using namespace shapevo;

constexpr int kIterations = 2000;
MpiSession* gMpi = nullptr;

void BM_BlockingAllreduce(benchmark::State& state) {
    MPI_Barrier(MPI_COMM_WORLD);
    double values[4] = {1, 2, 3, 4};
    for (auto _ : state) {
        MPI_Allreduce(MPI_IN_PLACE, values, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        benchmark::DoNotOptimize(values);
    }
}

void BM_Meeting(benchmark::State& state) {
    MeetingInput in;
    for (int g = 1; g <= state.range(0); ++g) {
        GenerationStats s;
        s.generation = std::uint32_t(g);
        s.best = 0.5 + 0.001 * g;
        in.rows.push_back(islandRow(s, std::vector<double>(200, 0.5)));
    }
    MPI_Barrier(MPI_COMM_WORLD);
    for (auto _ : state) {
        const MeetingResult m = meet(*gMpi, in);
        benchmark::DoNotOptimize(m.rows.data());
    }
}

void BM_SyncMigration(benchmark::State& state) {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/spaceship.grammar");
    const GenomeLimits limits{60};
    Population pop;
    Rng rng(7 + std::uint64_t(gMpi->rank()));
    for (int i = 0; i < 200; ++i) {
        Chromosome c;
        while (c.genes < 15 && grow(g, c, rng, limits)) {
        }
        pop.individuals.push_back(c);
        pop.fitness.push_back(0.001 * i);
    }
    MigrationSettings m;
    m.interval = 1;
    m.count = 5;
    const TreeFamily family(g);
    RingMigration migration(*gMpi, m, family, limits);
    MPI_Barrier(MPI_COMM_WORLD);
    std::uint32_t generation = 0;
    for (auto _ : state) migration.afterGeneration(pop, ++generation, pop.size());
    state.counters["received"] = double(migration.received());
    migration.finish();  // the last migrants are still in flight (sync exchanges complete one migration late)
}

void BM_AsyncStatus(benchmark::State& state) {
    AsyncControl control(*gMpi, 0.0);
    IslandStatus own;
    MPI_Barrier(MPI_COMM_WORLD);
    for (auto _ : state) {
        if (gMpi->rank() == 0) control.collect(own);
        else control.report(own, true);
    }
    control.finish();
}

BENCHMARK(BM_BlockingAllreduce)->Iterations(kIterations)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Meeting)->Arg(1)->Arg(20)->Iterations(kIterations)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SyncMigration)->Iterations(kIterations)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AsyncStatus)->Iterations(kIterations)->UseRealTime()->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
    MpiSession mpi(argc, argv);
    gMpi = &mpi;
    if (mpi.size() < 2) std::fprintf(stderr, "bench_island_exchange: run it under mpirun -np 2 or more\n");
    if (mpi.rank() != 0 && !std::freopen("/dev/null", "w", stdout)) return 1;
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
