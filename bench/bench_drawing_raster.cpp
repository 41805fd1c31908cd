// bench_drawing_raster: the exact raster for scoring graph-grammar drawings (graph/
// drawing_raster.hpp) at 256x256, per drawing: a derivation of grammars/graph/tree.yml (seed 1:
// circles and lines) and of grammars/graph/koch.yml (seed 1), the frame fitted to the drawing's
// canvas (margin 0.5). The derivation is done once, outside the timing; the raster object is
// warm (it allocates nothing per drawing).
//
//   cd build && ninja bench_drawing_raster && ./bench/bench_drawing_raster --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <string>

#include "graph/derive.hpp"
#include "graph/drawing.hpp"
#include "graph/drawing_raster.hpp"
#include "graph/read_graph_grammar.hpp"

#include "bench_main.hpp"

namespace {

using namespace shapevo::graph;

Drawing derived(const char* name) {
    const std::string file = std::string(SHAPEVO_SOURCE_DIR "/grammars/graph/") + name;
    const GraphGrammar g = readGraphGrammar(file);
    SeededDraws draws(1);
    const DeriveResult r = deriveGraph(g, 0, draws, DeriveLimits{});
    return drawingOf(r.graph, g.names, file);
}

void rasterize(benchmark::State& state, const char* name) {
    const Drawing drawing = derived(name);
    const RasterFrame frame = frameFitting(canvasOf(drawing, 0.5), 256, 256);
    DrawingRaster raster;
    std::int64_t covered = raster.rasterize(drawing, frame);
    for (auto _ : state) {
        covered = raster.rasterize(drawing, frame);
        benchmark::DoNotOptimize(covered);
    }
    state.counters["shapes"] = double(drawing.shapes.size());
    state.counters["covered"] = double(covered);
    state.counters["rasters/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_RasterTree256(benchmark::State& state) { rasterize(state, "tree.yml"); }
BENCHMARK(BM_RasterTree256)->Unit(benchmark::kMicrosecond);

void BM_RasterKoch256(benchmark::State& state) { rasterize(state, "koch.yml"); }
BENCHMARK(BM_RasterKoch256)->Unit(benchmark::kMicrosecond);

}  // namespace

SHAPEVO_BENCHMARK_MAIN();
