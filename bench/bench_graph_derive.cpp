// bench_graph_derive: 2D graph grammar derivations (src/graph/). (1) The original's Koch flake,
// 192 steps (the paper's), per derivation; the original takes 3.2–5.1 s per derivation on this
// kind of machine (graph-grammar README, section 5). (2) Koch to 100,000 steps (600,006
// elements): a step's cost must not grow with the graph. The SVG text is measured with the
// 192-step flake (BM_KochFlake192WithSvg). (3) Each shipped grammar of grammars/graph/ to its
// end (or its step limit). The original's files are read from
// ../shared/graph-grammar/original-examples (never copied); a benchmark whose file is absent is
// skipped with a message.
//
//   cd build && ninja bench_graph_derive && ./bench/bench_graph_derive --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>

#include "graph/derive.hpp"
#include "graph/drawing.hpp"
#include "graph/read_graph_grammar.hpp"
#include "graph/svg_writer.hpp"

#include "bench_main.hpp"

namespace {

using namespace shapevo::graph;

const GraphGrammar* load(const std::string& path) {
    static std::map<std::string, GraphGrammar> cache;
    if (!std::filesystem::exists(path)) return nullptr;
    auto it = cache.find(path);
    if (it == cache.end()) it = cache.emplace(path, readGraphGrammar(path)).first;
    return &it->second;
}

std::string original(const char* name) { return std::string(SHAPEVO_SOURCE_DIR "/../shared/graph-grammar/original-examples/") + name; }

void deriveSteps(benchmark::State& state, const std::string& path, std::int64_t steps, bool svg = false) {
    const GraphGrammar* g = load(path);
    if (!g) {
        state.SkipWithError(("absent: " + path).c_str());
        return;
    }
    std::uint64_t seed = 1;
    std::size_t elements = 0;
    for (auto _ : state) {
        SeededDraws draws(seed++);
        DeriveLimits limits;
        limits.maxSteps = steps;
        const DeriveResult r = deriveGraph(*g, 0, draws, limits);
        elements = r.graph.elements();
        benchmark::DoNotOptimize(elements);
        if (svg) {
            const Drawing drawing = drawingOf(r.graph, g->names, path);
            const std::string text = drawingSvg(drawing, g->filters, canvasOf(drawing, 0.5));
            benchmark::DoNotOptimize(text.data());
        }
    }
    state.counters["elements"] = double(elements);
    state.counters["derivations/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_KochFlake192(benchmark::State& state) { deriveSteps(state, original("koch_flake.yml"), 192); }
BENCHMARK(BM_KochFlake192)->Unit(benchmark::kMillisecond);

// The measure: a derivation and its SVG text (not written to disk).
void BM_KochFlake192WithSvg(benchmark::State& state) { deriveSteps(state, original("koch_flake.yml"), 192, true); }
BENCHMARK(BM_KochFlake192WithSvg)->Unit(benchmark::kMillisecond);

void BM_KochFlake10k(benchmark::State& state) { deriveSteps(state, original("koch_flake.yml"), 10'000); }
BENCHMARK(BM_KochFlake10k)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_KochFlake100k(benchmark::State& state) { deriveSteps(state, original("koch_flake.yml"), 100'000); }
BENCHMARK(BM_KochFlake100k)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Tree200(benchmark::State& state) { deriveSteps(state, original("tree.yml"), 200); }
BENCHMARK(BM_Tree200)->Unit(benchmark::kMillisecond);

void BM_PatternCircle(benchmark::State& state) { deriveSteps(state, original("pattern_circle.yml"), 0); }
BENCHMARK(BM_PatternCircle)->Unit(benchmark::kMillisecond);

void BM_PatternSquare(benchmark::State& state) { deriveSteps(state, original("pattern_square.yml"), 500); }
BENCHMARK(BM_PatternSquare)->Unit(benchmark::kMillisecond);

// shapevo's own grammars (grammars/graph/), each to its end or its file's step limit.
std::string own(const char* name) { return std::string(SHAPEVO_SOURCE_DIR "/grammars/graph/") + name; }
void BM_OwnKoch(benchmark::State& state) { deriveSteps(state, own("koch.yml"), 0); }
BENCHMARK(BM_OwnKoch)->Unit(benchmark::kMillisecond);
void BM_OwnTree(benchmark::State& state) { deriveSteps(state, own("tree.yml"), 0); }
BENCHMARK(BM_OwnTree)->Unit(benchmark::kMillisecond);
void BM_OwnRadial(benchmark::State& state) { deriveSteps(state, own("radial.yml"), 0); }
BENCHMARK(BM_OwnRadial)->Unit(benchmark::kMillisecond);
void BM_OwnTiled(benchmark::State& state) { deriveSteps(state, own("tiled.yml"), 0); }
BENCHMARK(BM_OwnTiled)->Unit(benchmark::kMillisecond);
void BM_OwnFacade(benchmark::State& state) { deriveSteps(state, own("facade.yml"), 0); }
BENCHMARK(BM_OwnFacade)->Unit(benchmark::kMillisecond);

}  // namespace

SHAPEVO_BENCHMARK_MAIN();
