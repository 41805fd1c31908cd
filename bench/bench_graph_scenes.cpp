// bench_graph_scenes: the 2D graph-grammar scenes' evaluations (docs/evolving-graph-grammars.md,
// "Measurements"). Per scene, on one thread: BM_Evaluate (what the search pays per model: the
// keyed derivation with its decision record, the drawing, the exact raster in the target's frame,
// the counts), and its parts: BM_Derive (the derivation alone), BM_Draw (derivation + drawing),
// BM_Raster (the raster of a drawing made once); BM_SharedPrefix: the share of a child's steps
// before its first changed decision (what starting from the parent's derivation could save). Models are the genomes the family's operators
// make from random genomes (a child: one grow, alter or regrow), as a search scores them.
//
//   cd build && ninja bench_graph_scenes && ./bench/bench_graph_scenes --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "genome/families/graph_family.hpp"
#include "graph/drawing_raster.hpp"
#include "run/config_file.hpp"
#include "run/models/loaded_model.hpp"
#include "run/scene.hpp"
#include "score/image/drawing_scorer.hpp"

#include "bench_main.hpp"

namespace {

using namespace shapevo;

struct SceneBench {
    RunSettings settings;
    std::unique_ptr<LoadedModel> model;
    std::unique_ptr<Scene> scene;
    std::vector<Chromosome> parents;   ///< 64 random genomes
    std::vector<Chromosome> children;  ///< a child of each
};

SceneBench& scene(const std::string& name) {
    static std::vector<std::pair<std::string, std::unique_ptr<SceneBench>>> cache;
    for (auto& [n, s] : cache)
        if (n == name) return *s;
    auto s = std::make_unique<SceneBench>();
    s->settings = loadConfig(std::string(SHAPEVO_SOURCE_DIR "/configs/") + name + ".toml");
    s->model = LoadedModel::load(s->settings);
    s->scene = Scene::load(s->settings, *s->model);
    auto ops = s->model->family().makeOperators(s->settings.limits);
    Rng rng(42);
    auto ws = s->scene->scorer().makeWorkspace();
    for (int i = 0; i < 64; ++i) {
        Chromosome parent, child;
        ops->randomGenome(parent, rng, 1, 1);
        s->scene->scorer().fitness(parent, *ws);  // its record, as scoring leaves it
        parent.lineage = Lineage{ws->made};
        child = parent;
        switch (i % 3) {
        case 0: ops->grow(child, rng); break;
        case 1: ops->alter(child, rng) || ops->grow(child, rng); break;
        default: if (!ops->regrow(parent, child, rng)) child = parent; break;
        }
        child.lineage = {};
        parent.lineage = {};
        s->parents.push_back(std::move(parent));
        s->children.push_back(std::move(child));
    }
    cache.emplace_back(name, std::move(s));
    return *cache.back().second;
}

/// Each iteration goes through all 64 children once (their costs vary widely: the same mix in
/// every benchmark); "models/s" is per child.
void perModel(benchmark::State& state, std::size_t models) {
    state.counters["models/s"] = benchmark::Counter(double(models), benchmark::Counter::kIsIterationInvariantRate);
}

void evaluate(benchmark::State& state, const char* name) {
    SceneBench& s = scene(name);
    auto ws = s.scene->scorer().makeWorkspace();
    for (auto _ : state)
        for (const Chromosome& c : s.children) benchmark::DoNotOptimize(s.scene->scorer().fitness(c, *ws));
    perModel(state, s.children.size());
}

void derive(benchmark::State& state, const char* name, bool draw) {
    SceneBench& s = scene(name);
    const GraphFamily& family = *s.model->graph();
    for (auto _ : state)
        for (const Chromosome& c : s.children) {
            const graph::DeriveResult r = family.derive(c);
            if (draw) benchmark::DoNotOptimize(family.drawing(r.graph).shapes.size());
            benchmark::DoNotOptimize(r.steps);
        }
    perModel(state, s.children.size());
}

void raster(benchmark::State& state, const char* name) {
    SceneBench& s = scene(name);
    const auto& scorer = static_cast<const DrawingScorer&>(s.scene->scorer());
    std::vector<graph::Drawing> drawings;
    for (const Chromosome& c : s.children) drawings.push_back(scorer.drawing(c));
    graph::DrawingRaster r;
    for (auto _ : state)
        for (const graph::Drawing& d : drawings) benchmark::DoNotOptimize(r.rasterize(d, scorer.frame()));
    perModel(state, drawings.size());
}

/// The steps a child shares with its parent: those before the first decision whose word differs
/// (its override added, removed or changed, or its event given another seed); a derivation is a
/// function of its words, so the steps before are the parent's, step for step. `childSteps` gets
/// the child's steps (its record has an event per step and one for the start).
std::uint32_t sharedSteps(const GraphFamily& family, const Chromosome& parent, const Chromosome& child, std::size_t& childSteps) {
    graph::DecisionRecord a, b;
    family.derive(parent, &a);
    childSteps = std::size_t(family.derive(child, &b).steps);
    const auto po = graphOverrides(parent), co = graphOverrides(child);
    auto sameOverride = [&](std::uint64_t key) {
        const std::ptrdiff_t i = graph::findOverride(po, key), j = graph::findOverride(co, key);
        if (i < 0 || j < 0) return i == j;
        return graph::overrideWord(po, std::size_t(i)) == graph::overrideWord(co, std::size_t(j));
    };
    for (std::size_t k = 0; k < std::min(a.decisions.size(), b.decisions.size()); ++k) {
        const graph::DecisionRecord::Decision &d = b.decisions[k], &e = a.decisions[k];
        const bool sameEvent = d.event < a.events.size() && d.event < b.events.size() &&
                               a.events[d.event].eventKey == b.events[d.event].eventKey && a.events[d.event].seed == b.events[d.event].seed;
        if (d.key != e.key || d.event != e.event || !sameEvent || !sameOverride(d.key)) return d.event;
    }
    return std::uint32_t(std::min(a.events.size(), b.events.size()));
}

/// What a child could skip if it started from its parent's derivation: the share of its steps
/// before its first changed decision (counters; the time is the 128 derivations that find it).
void sharedPrefix(benchmark::State& state, const char* name) {
    SceneBench& s = scene(name);
    const GraphFamily& family = *s.model->graph();
    double shared = 0, steps = 0;
    for (auto _ : state) {
        shared = steps = 0;
        for (std::size_t i = 0; i < s.children.size(); ++i) {
            std::size_t childSteps = 0;
            shared += sharedSteps(family, s.parents[i], s.children[i], childSteps);
            steps += double(childSteps);
        }
    }
    state.counters["shared steps %"] = 100 * shared / steps;
    state.counters["child steps"] = steps / double(s.children.size());
}

#define GRAPH_SCENE_BENCHES(id, name)                                                                  \
    void BM_Evaluate_##id(benchmark::State& s) { evaluate(s, name); }                                  \
    BENCHMARK(BM_Evaluate_##id)->Unit(benchmark::kMillisecond);                                         \
    void BM_Derive_##id(benchmark::State& s) { derive(s, name, false); }                               \
    BENCHMARK(BM_Derive_##id)->Unit(benchmark::kMillisecond);                                           \
    void BM_Draw_##id(benchmark::State& s) { derive(s, name, true); }                                  \
    BENCHMARK(BM_Draw_##id)->Unit(benchmark::kMillisecond);                                             \
    void BM_Raster_##id(benchmark::State& s) { raster(s, name); }                                      \
    BENCHMARK(BM_Raster_##id)->Unit(benchmark::kMillisecond);                                           \
    void BM_SharedPrefix_##id(benchmark::State& s) { sharedPrefix(s, name); }                          \
    BENCHMARK(BM_SharedPrefix_##id)->Unit(benchmark::kMillisecond)->Iterations(1);

GRAPH_SCENE_BENCHES(tree_sketch, "graph-tree-sketch")
GRAPH_SCENE_BENCHES(facade_reachable, "graph-facade-reachable")
GRAPH_SCENE_BENCHES(mosaic_logo, "graph-mosaic-logo")

}  // namespace

SHAPEVO_BENCHMARK_MAIN();
