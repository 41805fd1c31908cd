// bench_incremental: the same recorded GA children scored by the full evaluation and by the
// incremental one (score.incremental: the primitive cache and the duplicate memo), side by side.
//
// Recording (once per scene, not timed): the scene's GA runs from its config's seed on one thread
// up to generation FROM (default 1000), then the children of the next 50 generations are kept
// as the GA hands them to its evaluator (elites first, children after; each child with its
// lineage, so the incremental mode scores it from its parent where its operator named the change). Each benchmark iteration makes a
// fresh Evaluator on one thread, lets the incremental one score the 200 generations before FROM
// and the population of generation FROM (the children's parents), not timed, so that its cache is
// as warm and as grown as a run's is by then (its ring of records has wrapped: its memory written
// once, not page by page while timed; 50 generations did not do that), then times scoring the 50
// generations' children in order, dropping each generation's models once the next one is
// scored, as a run does. Counters: evals/s and s/child; duplicates, the share of
// children the memo answered; from_parent, the share scored from the parent's counts;
// model_bytes/individual, what the last generation's models keep for their children; cache_MB, the cache memory written after the 50 generations (one
// thread: an island's figure is this times its threads), and that per individual of the population. Both modes score exactly the same chromosomes; the fitnesses
// are compared and a difference aborts the benchmark.
//
//   cd build && ninja bench_incremental && ./bench/bench_incremental --benchmark_repetitions=5
//   SHAPEVO_BENCH_FROM=200 ./bench/bench_incremental     (children of earlier generations)
//   SHAPEVO_BENCH_KEEP_MODELS=1 ./bench/bench_incremental (every generation's models kept to the end)
//   SHAPEVO_BENCH_FRESH_CACHE=1 ./bench/bench_incremental (the cache warmed by the parents only)
//   SHAPEVO_BENCH_WARM=50 ./bench/bench_incremental       (warmed by 50 generations, as before 2026-12-06 10:00)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "bench_main.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "run/scene.hpp"
#include "score/image/image_model.hpp"
#include "score/image/image_scorer.hpp"
#include "search/search_methods.hpp"

namespace {

using namespace shapevo;

const char* const kScenes[] = {"tree-logo", "tree-sketch", "spaceship-paper", "spaceship", "castle-volume", "tree-volume"};
constexpr int kRecordedGenerations = 50;

struct Recording {
    RunSettings settings;
    std::unique_ptr<Grammar> grammar;
    std::unique_ptr<Scene> full, incremental;
    Population parents;
    std::vector<Population> before;       ///< the warmGenerations()' batches before FROM, no lineage
    std::vector<Population> generations;
    std::size_t elite = 0, children = 0;
    std::vector<double> fitness;  ///< every child's fitness (the full evaluation's), in order
};

/// Whether the environment variable `name` is "1".
bool switchedOn(const char* name) {
    const char* v = std::getenv(name);
    return v && std::string(v) == "1";
}

/// Generations before FROM that warm the cache (SHAPEVO_BENCH_WARM, default 200).
std::uint32_t warmGenerations() {
    const char* v = std::getenv("SHAPEVO_BENCH_WARM");
    return v ? std::uint32_t(std::strtoul(v, nullptr, 10)) : 200;
}

std::uint32_t fromGeneration() {
    const char* v = std::getenv("SHAPEVO_BENCH_FROM");
    return v ? std::uint32_t(std::strtoul(v, nullptr, 10)) : 1000;
}

Recording& recording(int scene) {
    static std::map<int, Recording> cache;
    auto it = cache.find(scene);
    if (it != cache.end()) return it->second;
    Recording& r = cache[scene];
    r.settings = loadConfig(std::string(SHAPEVO_SOURCE_DIR "/configs/") + kScenes[scene] + ".toml");
    r.settings.search.method = "ga";
    r.grammar = std::make_unique<Grammar>(loadGrammar(r.settings.grammarPath, r.settings.grammarAttrs));
    RunSettings off = r.settings;
    off.incremental.enabled = false;
    r.full = Scene::load(off, *r.grammar);
    RunSettings on = r.settings;
    on.incremental.enabled = true;
    r.incremental = Scene::load(on, *r.grammar);
    const TreeFamily family(*r.grammar);
    auto method = makeSearchMethod(r.settings.search, r.settings.population, r.settings.ga, family, r.settings.limits,
                                   r.settings.seed, r.settings.configPath);
    Evaluator evaluator(r.incremental->scorer(), 1);
    method->initialize(evaluator);
    const std::uint32_t from = fromGeneration();
    while (method->generation() + warmGenerations() < from) method->step(evaluator);
    // The generations before: what a run's caches hold by generation FROM (scored again untimed
    // before each pass, without their models).
    evaluator.observeBatches([&](const Population& p, std::size_t) {
        r.before.push_back(p);
        for (Chromosome& c : r.before.back().individuals) c.lineage = {};
    });
    while (method->generation() < from) method->step(evaluator);
    evaluator.observeBatches(nullptr);
    r.parents = method->population();
    // The children as the GA hands them to the evaluator: each with its lineage (the parent's
    // evaluation and the subtree its operator changed), which scoring would replace.
    evaluator.observeBatches([&](const Population& p, std::size_t) { r.generations.push_back(p); });
    for (int g = 0; g < kRecordedGenerations; ++g) {
        method->step(evaluator);
        const Population& scored = method->population();
        r.elite = std::size_t(r.settings.ga.elitism);
        r.children += scored.size() - r.elite;
        r.fitness.insert(r.fitness.end(), scored.fitness.begin() + std::ptrdiff_t(r.elite), scored.fitness.end());
    }
    evaluator.observeBatches(nullptr);
    return r;
}

/// Bytes the models of `pop` hold for their children (score/image/image_model.hpp): chromosome
/// copies and coverage counts, each shared block once.
std::size_t heldByModels(const Population& pop, const Scorer& scorer) {
    const auto* image = dynamic_cast<const ImageScorer*>(&scorer);  // (volume scorers keep no models)
    std::set<const void*> seen;
    std::size_t bytes = 0;
    for (const Chromosome& c : pop.individuals) {
        const EvaluatedModel* m = c.lineage.parent.get();
        if (!image || !m || m->maker != &image->models() || !seen.insert(m).second) continue;
        const auto& model = static_cast<const ImageModel&>(*m);
        bytes += sizeof(ImageModel) + model.chromosome.words.capacity() * sizeof(std::uint32_t);
        model.forEachBlockHeld([&](const void* block, std::size_t n) {
            if (seen.insert(block).second) bytes += n;
        });
    }
    return bytes;
}

void BM_ScoreRecordedChildren(benchmark::State& state) {
    const int scene = int(state.range(0));
    const bool incremental = state.range(1) != 0;
    Recording& r = recording(scene);
    const Scene& s = incremental ? *r.incremental : *r.full;
    state.SetLabel(std::string(kScenes[scene]) + (incremental ? " incremental" : " full") + ", children of generations " +
                   std::to_string(fromGeneration() + 1) + "-" + std::to_string(fromGeneration() + kRecordedGenerations));
    std::vector<Population> work;
    // SHAPEVO_BENCH_KEEP_MODELS=1: keep every generation's models to the end (as before 2026-12-06)
    const bool keepModels = switchedOn("SHAPEVO_BENCH_KEEP_MODELS");
    // SHAPEVO_BENCH_FRESH_CACHE=1: warm the cache with the parents only (as before 2026-12-06)
    const bool freshCache = switchedOn("SHAPEVO_BENCH_FRESH_CACHE");
    std::uint64_t reused = 0, fromParent = 0;
    std::size_t modelBytes = 0;
    std::size_t cacheBytes = 0;
    for (auto _ : state) {
        state.PauseTiming();
        work = r.generations;  // scoring replaces their lineage
        Evaluator evaluator(s.scorer(), 1);
        if (!freshCache && incremental)  // warm as a run's caches are at generation FROM: its last generations drawn
            for (const Population& p : r.before) {
                Population copy = p;
                evaluator.evaluate(copy);
            }
        Population parents = r.parents;
        evaluator.evaluate(parents);  // warm: the parents' primitives are in the cache
        const std::uint64_t reusedBefore = evaluator.reused();
        state.ResumeTiming();
        for (std::size_t k = 0; k < work.size(); ++k) {
            evaluator.evaluate(work[k], r.elite);
            // A run drops a generation's models once the next one has replaced it (and reuses them).
            if (k > 0 && !keepModels)
                for (Chromosome& c : work[k - 1].individuals) c.lineage = {};
        }
        state.PauseTiming();
        reused = evaluator.reused() - reusedBefore;
        fromParent = evaluator.scoredFromParent();
        modelBytes = heldByModels(work.back(), s.scorer());
        cacheBytes = evaluator.cacheBytesUsed();
        std::size_t k = 0;
        for (const Population& p : work)
            for (std::size_t i = r.elite; i < p.size(); ++i, ++k)
                if (p.fitness[i] != r.fitness[k]) {
                    std::fprintf(stderr, "bench_incremental: child %zu scores %.17g, recorded %.17g\n", k, p.fitness[i], r.fitness[k]);
                    std::abort();
                }
        state.ResumeTiming();
    }
    state.counters["children"] = double(r.children);
    state.counters["evals/s"] = benchmark::Counter(double(r.children), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["s/child"] = benchmark::Counter(double(r.children), benchmark::Counter::kIsIterationInvariantRate |
                                                                           benchmark::Counter::kInvert);
    state.counters["cache_MB"] = double(cacheBytes) / (1 << 20);  // written so far, one thread
    state.counters["bytes/individual"] = double(cacheBytes) / double(r.parents.size());
    state.counters["duplicates"] = double(reused) / double(r.children);
    state.counters["from_parent"] = double(fromParent) / double(r.children);  // scored from the parent's counts
    // What the last generation's models hold for their children (chromosome copies and coverage
    // counts, shared blocks once), per individual.
    state.counters["model_bytes/individual"] = double(modelBytes) / double(work.back().size());
}

// scene x {full, incremental}: the two modes of one scene run next to each other
BENCHMARK(BM_ScoreRecordedChildren)
    ->ArgNames({"scene", "incremental"})
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

SHAPEVO_BENCHMARK_MAIN()
