// Hot paths allocate nothing once warm: derive, voxelize + score, silhouettes of every kind and
// every genetic operator are run many times on reused buffers while a replaced global operator
// new counts allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "../score/random_primitives.hpp"
#include "../score/silhouette_test_util.hpp"
#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "genome/sample.hpp"
#include "graph/derive.hpp"
#include "graph/drawing_raster.hpp"
#include "graph/read_graph_grammar.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "score/image/image_scorer.hpp"
#include "score/volume/volume_scorer.hpp"

// AddressSanitizer (gcc says __SANITIZE_ADDRESS__, clang __has_feature) owns operator new.
#if defined(__SANITIZE_ADDRESS__)
#define SHAPEVO_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHAPEVO_TEST_ASAN 1
#endif
#endif
#if !defined(SHAPEVO_TEST_ASAN)
namespace {
std::atomic<long> gAllocations{0};
}
void* operator new(std::size_t n) {
    ++gAllocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
// The replaced operator new is malloc, so free is its match; GCC 12 still warns where it inlines
// these into allocator code (-Wmismatched-new-delete), depending on what else the file inlines.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace shapevo {
namespace {

TEST(NoAllocation, DeriveScoreAndOperatorsAllocateNothingOnceWarm) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    const VolumeTarget target = loadVolumeTarget({{test::sourcePath("targets/spaceship-reachable.vdb"), false}});
    const VolumeScorer scorer(g, target, FitnessSettings{});
    auto ws = scorer.makeWorkspace();
    const GenomeLimits limits{100};
    Rng rng(17);
    GenomeScratch scratch;
    std::vector<Chromosome> pop(16), next(16);
    // Warm every buffer to its largest size: full-length chromosomes and a first round of work.
    for (auto& c : pop) {
        c.words.reserve(100 * 16);
        while (grow(g, c, rng, limits)) {
        }
    }
    for (auto& c : next) c.words.reserve(100 * 16);
    scratch.newPos.reserve(100 * 16);
    ws->derive.stack.reserve(4096);
    ws->geometry.primitives.reserve(4096);
    double sink = 0;
    auto round = [&] {
        for (std::size_t i = 0; i < pop.size(); ++i) {
            sink += scorer.fitness(pop[i], *ws);
            const std::size_t j = (i + 5) % pop.size();
            crossover(g, pop[i], pop[j], next[i], next[j], rng, limits, 3, scratch);
            cut(g, next[i], rng, scratch);
            grow(g, next[i], rng, limits);
            alter(g, next[j], rng);
        }
        std::swap(pop, next);
    };
    for (int warm = 0; warm < 20; ++warm) round();
    const long before = gAllocations.load();
    for (int r = 0; r < 200; ++r) round();
    EXPECT_EQ(gAllocations.load() - before, 0) << "allocations in 200 rounds of 16 evaluations and operators";
    EXPECT_NE(sink, 0.0);
}

TEST(NoAllocation, VoxelizingEveryPrimitiveKindIncludingMeshesAllocatesNothingOnceWarm) {
    GridSpec grid;
    grid.origin = {-1.3, -0.7, 0.25};
    grid.voxelSize = 0.05;
    grid.nx = 100;
    grid.ny = 60;
    grid.nz = 50;
    Rng rng(23);
    const VolumeTarget target = test::randomTarget(grid, rng);
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    std::vector<Geometry> models(50);
    for (Geometry& m : models) {
        m.meshes = &meshes;
        for (int i = 0; i < 20; ++i)
            m.primitives.push_back(test::randomPrimitive(PrimitiveKind(rng.below(kPrimitiveKinds)), grid, rng, 2));
    }
    Voxelizer vox(grid);
    std::uint64_t sink = 0;
    for (const Geometry& m : models) sink += vox.score(m, target).occupied;  // warm
    const long before = gAllocations.load();
    for (int r = 0; r < 5; ++r)
        for (const Geometry& m : models) sink += vox.score(m, target).occupied;
    EXPECT_EQ(gAllocations.load() - before, 0) << "allocations in 250 evaluations of 20 primitives of every kind";
    EXPECT_NE(sink, 0u);
}

TEST(NoAllocation, ImageScoringOfTreesAllocatesNothingOnceWarm) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/tree.grammar"));
    for (Projection projection : {Projection::Perspective, Projection::Orthographic, Projection::Shadow}) {
        CameraSpec spec;
        spec.projection = projection;
        spec.eye = {0.0, 2.0, 12.0};
        spec.lookAt = {0.0, 2.0, 0.0};
        spec.viewHeight = 12.0;
        spec.groundY = -2.0;
        spec.groundMin = {-8.0, -6.0};
        spec.groundMax = {8.0, 6.0};
        const Camera camera = Camera::compile(spec, "test");
        const ImageTarget target =
            loadImageTarget(test::sourcePath("targets/shapegenetics/tree_target_sketch1.png"), PixelRule{}, 800, 600);
        const ImageScorer scorer(g, camera, target, FitnessSettings{});
        auto ws = scorer.makeWorkspace();
        Rng rng(23);
        const GenomeLimits limits{300};
        std::vector<Chromosome> pop(12);
        for (auto& c : pop)
            while (c.genes < 300 && grow(g, c, rng, limits)) {
            }
        double sink = 0;
        for (int warm = 0; warm < 3; ++warm)
            for (const auto& c : pop) sink += scorer.fitness(c, *ws);
        const long before = gAllocations.load();
        for (int r = 0; r < 20; ++r)
            for (const auto& c : pop) sink += scorer.fitness(c, *ws);
        EXPECT_EQ(gAllocations.load() - before, 0) << "projection " << int(projection);
        EXPECT_NE(sink, 0.0);
    }
}

/// Derives every chromosome of `pop` twice to warm one scratch, then `rounds` more times on it:
/// the allocations those rounds made (a test failure too if they derived nothing).
long allocationsDerivingWarm(const Grammar& g, const std::vector<Chromosome>& pop, int rounds, Geometry& out) {
    DeriveScratch scratch;
    std::size_t sink = 0;
    for (int warm = 0; warm < 2; ++warm)
        for (const auto& c : pop) sink += std::size_t(derive(g, c, out, scratch)) + out.primitives.size();
    const long before = gAllocations.load();
    for (int r = 0; r < rounds; ++r)
        for (const auto& c : pop) sink += std::size_t(derive(g, c, out, scratch)) + out.primitives.size();
    const long allocations = gAllocations.load() - before;
    EXPECT_GT(sink, 0u);
    return allocations;
}

TEST(NoAllocation, DerivingBuildingsAndCastlesAllocatesNothingOnceWarm) {
    // Splits, repeats, comp, lots, inline calls, lets and colours reuse derive's work space.
    for (const char* name : {"castle", "building"}) {
        const Grammar g = loadGrammar(test::sourcePath(std::string("grammars/") + name + ".grammar"));
        Rng rng(31);
        const GenomeLimits limits{40};
        std::vector<Chromosome> pop(12);
        for (auto& c : pop)
            while (c.genes < 40 && grow(g, c, rng, limits)) {
            }
        Geometry out;
        EXPECT_EQ(allocationsDerivingWarm(g, pop, 10, out), 0) << name;
        EXPECT_EQ(out.appearance.size(), out.primitives.size()) << name;
    }
}

TEST(NoAllocation, DerivingGrammarsWithListsAllocatesNothingOnceWarm) {
    // sends, gathers and their steps (orders, aggregates, groups, k-means, merge, ray casts,
    // facing) reuse the collections' work space
    for (const char* name : {"houses", "city-zones", "street-view", "street-numbers"}) {
        const Grammar g = loadGrammar(test::sourcePath(std::string("grammars/") + name + ".grammar"));
        std::vector<Chromosome> pop(8);
        for (std::size_t k = 0; k < pop.size(); ++k) {
            Rng rng{41 + k};
            ASSERT_TRUE(growUncontrolled(g, pop[k], rng, 40)) << name;
        }
        Geometry out;
        EXPECT_EQ(allocationsDerivingWarm(g, pop, 5, out), 0) << name;
    }
}

TEST(NoAllocation, DerivingATexturedGrammarAllocatesNothingOnceWarm) {
    // texture statements append to derive's looks and the geometry's texture frames: reused
    const Grammar g = loadGrammar(test::sourcePath("docs/grammar-examples/textures.grammar"));
    Rng rng(37);
    Chromosome c;
    plantRoot(g, c, rng);
    Geometry out;
    DeriveScratch scratch;
    std::size_t sink = 0;
    for (int warm = 0; warm < 2; ++warm) sink += std::size_t(derive(g, c, out, scratch)) + out.primitives.size();
    const long before = gAllocations.load();
    for (int r = 0; r < 20; ++r) sink += std::size_t(derive(g, c, out, scratch)) + out.textureFrames.size();
    EXPECT_EQ(gAllocations.load() - before, 0);
    EXPECT_GT(sink, 0u);
    EXPECT_EQ(out.textureFrames.size(), 3u) << "the keep's and each tower roof's";
}

TEST(NoAllocation, SilhouettesOfEveryPrimitiveKindAllocateNothingOnceWarm) {
    // every kind (roofs and paraboloids too), on the fast, cut and guard-band paths of each camera
    const std::vector<MeshShape> meshes = test::starMesh();
    for (const test::Scene& scene : test::scenes()) {
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        Rng rng(29);
        const ImageTarget target = test::randomTarget(camera.width(), camera.height(), rng);
        std::vector<Primitive> primitives(480);  // 60 models of 8
        for (Primitive& p : primitives) p = test::randomPrimitive(PrimitiveKind(rng.below(kPrimitiveKinds)), scene, rng);
        auto draw = [&] {
            std::uint64_t covered = 0;
            for (std::size_t i = 0; i < primitives.size(); ++i) {
                raster.add(primitives[i], &meshes);
                if (i % 8 == 7) covered += raster.score(target).covered;
            }
            return covered;
        };
        for (int warm = 0; warm < 2; ++warm) draw();
        const long before = gAllocations.load();
        const std::uint64_t covered = draw();
        EXPECT_EQ(gAllocations.load() - before, 0) << scene.name;
        EXPECT_GT(covered, 0u);
    }
}

// The raster for scoring graph-grammar drawings (graph/drawing_raster.hpp): derived trees and
// Koch flakes of every seed, rasterized again and again into one frame.
TEST(NoAllocation, RasterizingGraphGrammarDrawingsAllocatesNothingOnceWarm) {
    std::vector<graph::Drawing> drawings;
    for (const char* name : {"tree.yml", "koch.yml"}) {
        const std::string file = test::sourcePath(std::string("grammars/graph/") + name);
        const graph::GraphGrammar g = graph::readGraphGrammar(file);
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            graph::SeededDraws draws(seed);
            const graph::DeriveResult r = graph::deriveGraph(g, 0, draws, graph::DeriveLimits{});
            drawings.push_back(graph::drawingOf(r.graph, g.names, file));
        }
    }
    graph::Shape path;  // a filled and stroked path of curves too (the grammars draw none)
    path.kind = graph::ShapeKind::Path;
    path.attributes = {{"d", "M0 0 C50 80 100 -20 150 60 Q80 120 20 90 Z M30 30 L60 40 L40 70 Z"},
                       {"fill", "red"}, {"stroke", "black"}, {"stroke-linejoin", "round"}, {"stroke-width", "3"}};
    drawings.back().shapes.push_back(path);
    const graph::RasterFrame frame = graph::frameFitting(graph::canvasOf(drawings[0], 0.5), 256, 256);
    graph::DrawingRaster raster;
    for (int warm = 0; warm < 2; ++warm)
        for (const graph::Drawing& d : drawings) raster.rasterize(d, frame);
    const long before = gAllocations.load();
    std::int64_t covered = 0;
    for (int round = 0; round < 5; ++round)
        for (const graph::Drawing& d : drawings) covered += raster.rasterize(d, frame);
    EXPECT_EQ(gAllocations.load() - before, 0);
    EXPECT_GT(covered, 0);
}

}  // namespace
}  // namespace shapevo
#endif
