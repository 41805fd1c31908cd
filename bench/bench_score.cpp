// bench_score: voxelize + score, the second half (and the bulk) of a fitness evaluation.
//  - BM_DeriveScore/<grid>: VolumeScorer::fitness (derive + voxelize + count + fitness) over a
//    population of 200 random spaceship chromosomes (initial lengths uniform in [2, 40] as in the
//    GA, fixed seed), round-robin, one workspace.
//  - BM_DeriveOnly: derive() alone over the same 200 chromosomes (no grid involved).
//  - BM_ScoreOnly/<grid>: the same 200 models derived once up front; only Voxelizer::score timed.
//  - BM_RandomBoxes/<rotated>: 20 random oriented boxes (random unit quaternion, half extents
//    0.2..1.0, centres inside the reachable target's grid) scored directly; rotated=0 gives
//    axis-aligned boxes of the same sizes (the voxelizer's fast path) for comparison.
// Grids: reachable = targets/spaceship-reachable.vdb with its default padded grid; paper =
// targets/spaceship-paper.vdb on the papers' grid (min (-5,-5,-2), max (5,5,18), voxel 0.1).
// Counters: evals/s; voxel_rows/s = rows a primitive was rasterized into, per second
// (VoxelCounts::rows, the work the sparse voxelizer really does); grid_rows/s = evals/s x the
// grid's ny*nz rows, i.e. the rows of the target grid each evaluation scores, which a dense
// voxelizer (like the papers' GPU one) must sweep for every model; rows/eval.
//
//   cd build && ninja bench_score && taskset -c 1 ./bench/bench_score --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/volume/volume_scorer.hpp"

namespace {

using namespace shapevo;

constexpr std::size_t kPopulation = 200;

const Grammar& spaceship() {
    static const Grammar g = loadGrammar(SHAPEVO_SOURCE_DIR "/grammars/spaceship.grammar");
    return g;
}
const VolumeTarget& reachableTarget() {
    static const VolumeTarget t =
        loadVolumeTarget({TargetVolumeSpec{SHAPEVO_SOURCE_DIR "/targets/spaceship-reachable.vdb", false}});
    return t;
}
const VolumeTarget& paperTarget() {
    static const VolumeTarget t = [] {
        GridOverride grid;
        grid.min = glm::dvec3(-5, -5, -2);
        grid.max = glm::dvec3(5, 5, 18);
        grid.voxelSize = 0.1;
        return loadVolumeTarget({TargetVolumeSpec{SHAPEVO_SOURCE_DIR "/targets/spaceship-paper.vdb", false}}, &grid);
    }();
    return t;
}
const VolumeTarget& targetFor(std::int64_t which) { return which == 0 ? reachableTarget() : paperTarget(); }

/// 200 random spaceships, grown like GeneticAlgorithm::initialize (length uniform in [2, 40]).
const std::vector<Chromosome>& population() {
    static const std::vector<Chromosome> pop = [] {
        const GenomeLimits limits{100};
        Rng rng(1);
        std::vector<Chromosome> v(kPopulation);
        for (Chromosome& c : v) {
            const std::uint32_t length = 2 + rng.below(40 - 2 + 1);
            while (c.genes < length && grow(spaceship(), c, rng, limits)) {
            }
        }
        return v;
    }();
    return pop;
}

std::string gridLabel(const char* what, const GridSpec& g) {
    return std::string(what) + " " + std::to_string(g.nx) + "x" + std::to_string(g.ny) + "x" + std::to_string(g.nz) +
           " @" + std::to_string(g.voxelSize).substr(0, 5);
}

void setCounters(benchmark::State& state, std::uint64_t rows, const GridSpec* grid = nullptr) {
    state.SetItemsProcessed(state.iterations());
    if (grid)
        state.counters["grid_rows/s"] =
            benchmark::Counter(double(state.iterations()) * double(grid->rows()), benchmark::Counter::kIsRate);
    state.counters["evals/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["voxel_rows/s"] = benchmark::Counter(double(rows), benchmark::Counter::kIsRate);
    state.counters["rows/eval"] = benchmark::Counter(double(rows), benchmark::Counter::kAvgIterations);
}

void BM_DeriveScore(benchmark::State& state) {
    const VolumeTarget& target = targetFor(state.range(0));
    const VolumeScorer scorer(spaceship(), target, FitnessSettings{});
    const auto& pop = population();
    auto ws = std::make_unique<VolumeScorer::Workspace>(target.grid);
    VoxelCounts counts;
    for (const Chromosome& c : pop) scorer.fitness(c, *ws, &counts);  // warm every buffer
    std::uint64_t rows = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const double f = scorer.fitness(pop[i], *ws, &counts);
        benchmark::DoNotOptimize(f);
        rows += counts.rows;
        if (++i == pop.size()) i = 0;
    }
    setCounters(state, rows, &target.grid);
    state.SetLabel(gridLabel(state.range(0) == 0 ? "reachable grid" : "paper grid", target.grid));
}

void BM_ScoreOnly(benchmark::State& state) {
    const VolumeTarget& target = targetFor(state.range(0));
    const auto& pop = population();
    std::vector<Geometry> models(pop.size());
    DeriveScratch scratch;
    for (std::size_t k = 0; k < pop.size(); ++k) derive(spaceship(), pop[k], models[k], scratch);
    Voxelizer voxelizer(target.grid);
    for (const Geometry& m : models) voxelizer.score(m, target);  // warm
    std::uint64_t rows = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const VoxelCounts counts = voxelizer.score(models[i], target);
        benchmark::DoNotOptimize(counts);
        rows += counts.rows;
        if (++i == models.size()) i = 0;
    }
    setCounters(state, rows, &target.grid);
    state.SetLabel(gridLabel(state.range(0) == 0 ? "reachable grid" : "paper grid", target.grid));
}

/// The derive half alone over the same population, so derive+score can be split into its parts.
void BM_DeriveOnly(benchmark::State& state) {
    const auto& pop = population();
    DeriveScratch scratch;
    Geometry geometry;
    for (const Chromosome& c : pop) derive(spaceship(), c, geometry, scratch);  // warm
    std::uint64_t primitives = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        derive(spaceship(), pop[i], geometry, scratch);
        benchmark::DoNotOptimize(geometry.primitives.data());
        benchmark::ClobberMemory();
        primitives += geometry.primitives.size();
        if (++i == pop.size()) i = 0;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["evals/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["primitives/s"] = benchmark::Counter(double(primitives), benchmark::Counter::kIsRate);
    state.counters["primitives/eval"] = benchmark::Counter(double(primitives), benchmark::Counter::kAvgIterations);
    state.SetLabel("derive only, same 200 models");
}

/// Uniform random rotation (Shoemake's method: a uniform unit quaternion).
glm::mat3 randomRotation(Rng& rng) {
    const double u1 = rng.uniform(), u2 = rng.uniform() * 2 * M_PI, u3 = rng.uniform() * 2 * M_PI;
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const glm::quat q(float(b * std::cos(u3)), float(a * std::sin(u2)), float(a * std::cos(u2)), float(b * std::sin(u3)));
    return glm::mat3_cast(glm::normalize(q));
}

void BM_RandomBoxes(benchmark::State& state) {
    const bool rotated = state.range(0) != 0;
    const VolumeTarget& target = reachableTarget();
    const GridSpec& grid = target.grid;
    Rng rng(2024);
    Geometry geometry;
    std::vector<Primitive>& boxes = geometry.primitives;
    boxes.resize(20);
    const glm::dvec3 extent(grid.nx * grid.voxelSize, grid.ny * grid.voxelSize, grid.nz * grid.voxelSize);
    for (Primitive& p : boxes) {
        p.axes = randomRotation(rng);
        if (!rotated) p.axes = glm::mat3(1.0f);
        for (int k = 0; k < 3; ++k) {
            p.half[k] = float(0.2 + 0.8 * rng.uniform());
            p.centre[k] = float(grid.origin[k] + rng.uniform() * extent[k]);
        }
    }
    Voxelizer voxelizer(grid);
    voxelizer.score(geometry, target);  // warm
    std::uint64_t rows = 0;
    for (auto _ : state) {
        const VoxelCounts counts = voxelizer.score(geometry, target);
        benchmark::DoNotOptimize(counts);
        rows += counts.rows;
    }
    setCounters(state, rows);
    state.SetLabel(gridLabel(rotated ? "20 rotated boxes, reachable grid" : "20 axis-aligned boxes, reachable grid", grid));
}

BENCHMARK(BM_DeriveScore)->ArgName("paper")->Arg(0)->Arg(1);
BENCHMARK(BM_DeriveOnly);
BENCHMARK(BM_ScoreOnly)->ArgName("paper")->Arg(0)->Arg(1);
BENCHMARK(BM_RandomBoxes)->ArgName("rotated")->Arg(1)->Arg(0);

}  // namespace

BENCHMARK_MAIN();
