// bench_image_score: silhouette scoring against an 800 x 600 image target (the papers' tree
// scene: perspective, 60 degrees, the mickey logo as target).
//  - BM_ImageScore: SilhouetteRaster::add + score + imageFitness on pre-derived trees of about
//    200 primitives (cylinder branches, sphere leaf clusters); 16 different trees round-robin.
//  - BM_ImageDeriveScore: ImageScorer::fitness (derive + the above) on the same 16 chromosomes.
//  - BM_ImageScoreCylinders: the same trees with cylinders for leaves too (all one kind).
//  - BM_LargeTree/<part>: one 50,000-gene tree chromosome (every branch has three children,
//    breadth first); part 0 = derive + score (ImageScorer::fitness), 1 = derive only, 2 = score only.
//  - BM_LargeTreeChild/op:<k>/incremental:<0|1|2>/genes:<n>: children of such a tree of n genes by
//    one operator (0 alter, 1 grow, 2 cut), scored in full (0), incrementally (1) or incrementally
//    without the subtree memo (2), after the parent and enough children to warm the caches
//    (issue 15's 0.5 ms line). SHAPEVO_BENCH_CACHE_MB=512 sets score.cache_mb (default 128).
//  - BM_RasterizeKind/kind:<k>: SilhouetteRaster::add + score of 20 random rotated primitives of
//    one kind (0 box, 1 cylinder, 2 cone, 3 sphere, 5 roof, 6 paraboloid; half extents 0.1..0.5
//    around the tree's place in the view, fixed seed), to compare the kinds' outline costs.
// Counters: evals/s; primitives, covered pixels and rasterized rows per evaluation.
//
//   cd build && ninja bench_image_score && taskset -c 1 ./bench/bench_image_score --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "bench_main.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "score/image/image_scorer.hpp"
#include "shape/kinds.hpp"

#include <glm/gtc/quaternion.hpp>

#include "genome/random.hpp"

#include "breadth_first_tree.hpp"

namespace {

using namespace shapevo;

// After the papers' tree grammar (reference-targets/README.md): a trunk of height 1.4..1.8, up to
// three branches per branch (turn about the parent's axis, inclination 35..85 degrees, sizes
// 0.6..0.7 of the parent's), attached at 0.38 of the parent's height; a leaf cluster at 0.75 of
// the height of every branch without children, five times as wide as that branch.
std::string treeGrammar(const char* leaf) {
    return std::string(R"(
start Trunk
rule Trunk {
  param height = uniform(1.4, 1.8)
  size (0.25, height, 0.25)
  translate (0, scope.size.y * 0.5, 0)
  cylinder
  translate (0, scope.size.y * -0.12, 0)
  child Branch prob 0.9 max 3
}
rule Branch {
  param turn = uniform(0, 360)
  param tilt = uniform(35, 85)
  param shrink = uniform((0.6, 0.6, 0.6), (0.7, 0.8, 0.7))
  rotate y turn
  rotate x tilt
  scale shrink
  translate (0, scope.size.y * 0.5, 0)
  cylinder
  translate (0, scope.size.y * -0.12, 0)
  child Branch prob 0.75 max 3
  terminal {
    translate (0, scope.size.y * 0.25, 0)
    size (scope.size.x * 5, scope.size.x * 5, scope.size.x * 5)
    )") + leaf + R"(
  }
}
)";
}

const Grammar& tree(bool cylinderLeaves) {
    static const Grammar spheres = parseGrammar(treeGrammar("sphere"), "bench-tree.grammar");
    static const Grammar cylinders = parseGrammar(treeGrammar("cylinder"), "bench-tree-cylinders.grammar");
    return cylinderLeaves ? cylinders : spheres;
}

Camera paperCamera() {
    CameraSpec s;  // 800 x 600, 60 degrees, near 0.1; the tree spans about 250 x 200 pixels, like the logo
    s.eye = {0.0, 1.4, 5.0};
    s.lookAt = {0.0, 1.4, 0.0};
    return Camera::compile(s, "bench");
}

const ImageTarget& mickey() {
    static const ImageTarget t =
        loadImageTarget(SHAPEVO_SOURCE_DIR "/targets/shapegenetics/tree_target_mickey.png", PixelRule{}, 800, 600);
    return t;
}

/// Chromosomes grown with fixed seeds until their trees have about 200 primitives.
const std::vector<Chromosome>& trees() {
    static const std::vector<Chromosome> pop = [] {
        std::vector<Chromosome> v;
        DeriveScratch scratch;
        Geometry geometry;
        for (std::uint64_t seed = 1; v.size() < 16; ++seed) {
            Rng rng(seed);
            Chromosome c;
            const GenomeLimits limits{1000};
            do {
                if (!grow(tree(false), c, rng, limits)) break;
                derive(tree(false), c, geometry, scratch);
            } while (geometry.primitives.size() < 195);
            if (geometry.primitives.size() >= 195 && geometry.primitives.size() <= 215) v.push_back(c);
        }
        return v;
    }();
    return pop;
}

void setCounters(benchmark::State& state, std::uint64_t primitives, std::uint64_t covered, std::uint64_t rows) {
    state.SetItemsProcessed(state.iterations());
    state.counters["evals/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["primitives/eval"] = benchmark::Counter(double(primitives), benchmark::Counter::kAvgIterations);
    state.counters["pixels/eval"] = benchmark::Counter(double(covered), benchmark::Counter::kAvgIterations);
    state.counters["rows/eval"] = benchmark::Counter(double(rows), benchmark::Counter::kAvgIterations);
}

void scoreOnly(benchmark::State& state, bool cylinderLeaves) {
    const Grammar& g = tree(cylinderLeaves);
    const Camera camera = paperCamera();
    const FitnessSettings settings;
    std::vector<Geometry> models(trees().size());
    DeriveScratch scratch;
    for (std::size_t k = 0; k < models.size(); ++k) derive(g, trees()[k], models[k], scratch);
    SilhouetteRaster raster(camera);
    for (const Geometry& m : models) raster.add(m), raster.score(mickey());  // warm
    std::uint64_t primitives = 0, covered = 0, rows = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        raster.add(models[i]);
        const SilhouetteCounts counts = raster.score(mickey());
        const double f = imageFitness(settings, counts, mickey().hitCount, trees()[i].genes);
        benchmark::DoNotOptimize(f);
        primitives += models[i].primitives.size();
        covered += counts.covered;
        rows += counts.rows;
        if (++i == models.size()) i = 0;
    }
    setCounters(state, primitives, covered, rows);
}

void BM_ImageScore(benchmark::State& state) { scoreOnly(state, false); }
void BM_ImageScoreCylinders(benchmark::State& state) { scoreOnly(state, true); }

void BM_ImageDeriveScore(benchmark::State& state) {
    const Camera camera = paperCamera();
    const ImageScorer scorer(tree(false), camera, mickey(), FitnessSettings{});
    ImageScorer::Workspace ws(camera);
    SilhouetteCounts counts;
    for (const Chromosome& c : trees()) scorer.fitness(c, ws, &counts);  // warm
    std::uint64_t primitives = 0, covered = 0, rows = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const double f = scorer.fitness(trees()[i], ws, &counts);
        benchmark::DoNotOptimize(f);
        primitives += ws.geometry.primitives.size();
        covered += counts.covered;
        rows += counts.rows;
        if (++i == trees().size()) i = 0;
    }
    setCounters(state, primitives, covered, rows);
}

/// A full ternary tree of `genes` genes, built breadth first (every branch gets three children
/// until the count is reached), parameters drawn from the priors with a fixed seed.
Chromosome largeTree(std::uint32_t genes) {
    const Grammar& g = tree(false);
    std::uint16_t branch = 0;
    while (g.rules[branch].name != "Branch") ++branch;
    return bench::breadthFirstTree(g, genes, {branch});
}

void BM_LargeTree(benchmark::State& state) {
    const int part = int(state.range(0));
    const Camera camera = paperCamera();
    const ImageScorer scorer(tree(false), camera, mickey(), FitnessSettings{});
    static const Chromosome c = largeTree(50000);
    ImageScorer::Workspace ws(camera);
    SilhouetteCounts counts;
    scorer.fitness(c, ws, &counts);  // warm
    std::uint64_t primitives = 0, covered = 0, rows = 0;
    for (auto _ : state) {
        if (part == 0) {
            benchmark::DoNotOptimize(scorer.fitness(c, ws, &counts));
        } else if (part == 1) {
            derive(scorer.grammar(), c, ws.geometry, ws.derive);
            benchmark::DoNotOptimize(ws.geometry.primitives.data());
        } else {
            ws.raster.add(ws.geometry);
            counts = ws.raster.score(mickey());
        }
        primitives += ws.geometry.primitives.size();
        covered += counts.covered;
        rows += counts.rows;
    }
    setCounters(state, primitives, covered, rows);
    state.counters["genes"] = double(c.genes);
    state.SetLabel(part == 0 ? "derive + score" : part == 1 ? "derive only" : "score only");
}

/// Children of a large tree (largeTree of `genes` genes), one operator each (0 alter: new
/// parameters for one random gene; 1 grow: a new subtree; 2 cut: a subtree removed), scored in
/// full or incrementally (from the scored parent's counts, Lineage, where the operator names its change) (score.cache_mb 128 MB unless SHAPEVO_BENCH_CACHE_MB says otherwise, on
/// one workspace that has scored the parent and warm-up children first). Making the child (a copy
/// of the parent and the operator) is not timed. Counters per timed child: primitives, the share
/// of them copied from the subtree memo, the primitive cache's hits and misses and the memo's;
/// the cache memory written and whether the primitive cache is full.
void BM_LargeTreeChild(benchmark::State& state) {
    const int op = int(state.range(0));
    const bool incremental = state.range(1) != 0;
    const Camera camera = paperCamera();
    const Grammar& g = tree(false);
    ImageScorer scorer(g, camera, mickey(), FitnessSettings{});
    static std::map<std::int64_t, Chromosome> parents;
    if (!parents.count(state.range(2))) parents[state.range(2)] = largeTree(std::uint32_t(state.range(2)));
    const Chromosome& parent = parents[state.range(2)];
    const char* mb = std::getenv("SHAPEVO_BENCH_CACHE_MB");  // score.cache_mb (default 128)
    const std::size_t cacheBytes = incremental ? std::size_t(mb ? std::atoi(mb) : 128) << 20 : 0;
    scorer.setIncremental(cacheBytes);  // (its models, too, are bounded by score.cache_mb)
    ImageScorer::Workspace ws(camera, cacheBytes);
    if (state.range(1) == 2) ws.derive.memo->turnOff();  // the primitive caches alone
    SilhouetteCounts counts;
    Rng rng(11);
    GenomeScratch scratch;
    const GenomeLimits limits{60000};
    // The parent as a run holds it after scoring it: with what its children start from (Lineage).
    Chromosome scored = parent;
    scorer.fitness(scored, ws, &counts);
    scored.lineage = Lineage{std::move(ws.made)};
    Chromosome child;
    auto makeChild = [&] {
        do {
            child = scored;
        } while (!(op == 0 ? alter(g, child, rng) : op == 1 ? grow(g, child, rng, limits) : cut(g, child, rng, scratch)));
    };
    // Warm, as in a run: the parent, then children until the caches have grown to their size
    // (each growth forgets what they held), twice as many as the last growth took.
    std::size_t warm = 0;
    for (std::size_t last = 0; warm < 2 * last + 8; ++warm) {
        const std::size_t before = ws.cacheBytesUsed();
        makeChild();
        scorer.fitness(warm == 0 ? scored : child, ws, &counts);
        if (ws.cacheBytesUsed() > before + (1 << 20)) last = warm;
    }
    const auto statsBefore = ws.cache ? ws.cache->stats() : PrimitiveCache<WordMask>::Stats{};
    const auto memoBefore = ws.derive.memo ? ws.derive.memo->stats() : SubtreeMemo::Stats{};
    std::uint64_t primitives = 0, copied = 0;
    const std::uint64_t fromParentBefore = ws.fromParent;
    for (auto _ : state) {
        state.PauseTiming();
        makeChild();
        state.ResumeTiming();
        benchmark::DoNotOptimize(scorer.fitness(child, ws, &counts));
        primitives += ws.geometry.primitives.size();
        for (const DeriveScratch::ReusedSubtree& r : ws.derive.reused) copied += r.count;
    }
    const double n = double(state.iterations());
    if (ws.cache) {
        state.counters["cache_hits"] = double(ws.cache->stats().hits - statsBefore.hits) / n;
        state.counters["cache_misses"] = double(ws.cache->stats().misses - statsBefore.misses) / n;
        state.counters["warm_children"] = double(warm);
        state.counters["cache_full"] = ws.cache->full();
    }
    if (ws.derive.memo) {
        const SubtreeMemo::Stats m = ws.derive.memo->stats();
        state.counters["memo_hits"] = double(m.hits - memoBefore.hits) / n;
        state.counters["memo_misses"] = double(m.misses - memoBefore.misses) / n;
        state.counters["memo_outgrown"] = m.outgrown;
    }
    state.counters["from_parent"] = double(ws.fromParent - fromParentBefore) / n;  // scored from the parent's counts
    state.counters["primitives"] = double(primitives) / n;
    state.counters["copied"] = primitives ? double(copied) / double(primitives) : 0.0;
    state.counters["cache_MB"] = double(ws.cacheBytesUsed()) / (1 << 20);
    state.SetLabel(std::string(op == 0 ? "alter" : op == 1 ? "grow" : "cut") + (!incremental ? ", full" : state.range(1) == 1 ? ", incremental" : ", incremental without the memo"));
}

double between(Rng& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

void BM_RasterizeKind(benchmark::State& state) {
    const Camera camera = paperCamera();
    Rng rng(7);
    std::vector<Geometry> models(16);
    for (Geometry& m : models) {
        for (int k = 0; k < 20; ++k) {
            Primitive p;
            p.kind = PrimitiveKind(state.range(0));
            const float taper = float(between(rng, 0.0, 1.0)), taperZ = float(between(rng, 0.0, 1.0));
            if (p.kind == PrimitiveKind::Cone) setParams<ConeKind>(p, {taper});
            if (p.kind == PrimitiveKind::Roof) setParams<RoofKind>(p, {taper, taperZ});
            p.centre = {float(between(rng, -1.0, 1.0)), float(between(rng, 0.6, 2.2)), float(between(rng, -0.5, 0.5))};
            p.half = {float(between(rng, 0.1, 0.5)), float(between(rng, 0.1, 0.5)), float(between(rng, 0.1, 0.5))};
            const glm::quat q = glm::normalize(glm::quat(float(between(rng, -1.0, 1.0)), float(between(rng, -1.0, 1.0)),
                                                         float(between(rng, -1.0, 1.0)), float(between(rng, -1.0, 1.0))));
            p.axes = glm::mat3_cast(q);
            m.primitives.push_back(p);
        }
    }
    SilhouetteRaster raster(camera);
    for (const Geometry& m : models) raster.add(m), raster.score(mickey());  // warm
    std::uint64_t primitives = 0, covered = 0, rows = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        raster.add(models[i]);
        const SilhouetteCounts counts = raster.score(mickey());
        benchmark::DoNotOptimize(counts);
        primitives += models[i].primitives.size();
        covered += counts.covered;
        rows += counts.rows;
        if (++i == models.size()) i = 0;
    }
    setCounters(state, primitives, covered, rows);
    state.counters["primitives/s"] = benchmark::Counter(double(primitives), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_RasterizeKind)->ArgName("kind")->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Arg(5)->Arg(6);
BENCHMARK(BM_ImageScore);
BENCHMARK(BM_ImageScoreCylinders);
BENCHMARK(BM_ImageDeriveScore);
BENCHMARK(BM_LargeTree)->ArgName("part")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
// op x {full, incremental, incremental without the memo} x genes: the modes of one operator side by side
BENCHMARK(BM_LargeTreeChild)->ArgNames({"op", "incremental", "genes"})->ArgsProduct({{0, 1, 2}, {0, 1, 2}, {50000, 10000}})->Unit(benchmark::kMillisecond);

}  // namespace

SHAPEVO_BENCHMARK_MAIN()
