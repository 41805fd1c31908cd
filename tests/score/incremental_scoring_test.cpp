// Incremental scoring (score/primitive_cache.hpp and the replay paths of SilhouetteRaster and
// Voxelizer): a primitive's recorded rows replay to the very pixels and voxels drawing it gives,
// for every primitive kind and camera; the cache finds only bit-identical primitives and forgets
// overwritten ones as misses; scorers give the same fitness and counts with and without a cache,
// cold or warm; the checking mode stops on a cache that lies.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "genome/operators.hpp"
#include "grammar/front_ends.hpp"
#include "score/image/image_scorer.hpp"
#include "../model_stream.hpp"
#include "../small_tree_grammar.hpp"
#include "../test_support.hpp"
#include "score/primitive_cache.hpp"
#include "score/volume/volume_scorer.hpp"
#include "random_primitives.hpp"
#include "silhouette_test_util.hpp"

namespace shapevo {
namespace {

TEST(IncrementalScoring, RecordedRowsReplayToTheSamePixelsForEveryKindAndCamera) {
    const std::vector<MeshShape> meshes = test::starMesh();
    for (const test::Scene& scene : test::scenes()) {
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster drawn(camera), replayed(camera);
        Rng rng(11);
        const ImageTarget target = test::randomTarget(camera.width(), camera.height(), rng);
        for (int k = 0; k < kPrimitiveKinds; ++k) {
            SCOPED_TRACE(std::string(scene.name) + " kind " + std::to_string(k));
            long nonEmpty = 0;
            for (int i = 0; i < 300; ++i) {
                const Primitive p = test::randomPrimitive(PrimitiveKind(k), scene, rng);
                drawn.add(p, &meshes);
                std::vector<RowSpan> spans;
                replayed.addRecorded(p, &meshes, spans);
                ASSERT_EQ(replayed.bits(), drawn.bits()) << "recording drew other pixels, primitive " << i;
                replayed.clear();
                std::vector<WordMask> words;
                replayed.wordMasks(spans, words);
                replayed.replay(words, SilhouetteRaster::boundsOf(spans));
                ASSERT_EQ(replayed.bits(), drawn.bits()) << "replay drew other pixels, primitive " << i;
                const SilhouetteCounts a = drawn.score(target), b = replayed.score(target);
                ASSERT_EQ(a.covered, b.covered);
                ASSERT_EQ(a.hit, b.hit);
                ASSERT_EQ(a.avoided, b.avoided);
                nonEmpty += a.covered > 0;
                for (std::size_t s = 1; s < spans.size(); ++s)  // merged: one interval per run of pixels
                    ASSERT_TRUE(spans[s].y > spans[s - 1].y || spans[s].lo > spans[s - 1].hi + 1);
            }
            EXPECT_GT(nonEmpty, 100);
        }
    }
}

/// The counts without the work measure (a replay rasterizes no row).
VoxelCounts withoutWork(VoxelCounts c) {
    c.rows = 0;
    return c;
}

TEST(IncrementalScoring, RecordedVoxelRunsReplayToTheSameCountsForEveryKind) {
    GridSpec grid;
    grid.origin = {-1.3, -0.7, 0.25};
    grid.voxelSize = 0.1;
    grid.nx = 70, grid.ny = 23, grid.nz = 17;
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    Rng rng(5);
    const VolumeTarget target = test::randomTarget(grid, rng);
    Voxelizer full(grid), cached(grid);
    long nonEmpty = 0;
    for (int model = 0; model < 400; ++model) {
        Geometry g;
        g.meshes = &meshes;
        for (int i = 0; i < 6; ++i) {
            Primitive p = test::randomPrimitive(PrimitiveKind(rng.below(kPrimitiveKinds)), grid, rng, 2);
            if (p.kind == PrimitiveKind::Mesh) setParams<MeshKind>(p, {std::uint16_t(rng.below(2))});
            g.primitives.push_back(p);
        }
        const VoxelCounts want = full.score(g, target);
        // first pass records each primitive, second replays them all
        VoxelCounts counts;
        std::vector<std::vector<VoxelRun>> runs(g.primitives.size());
        std::vector<std::uint64_t> outside(g.primitives.size());
        for (std::size_t i = 0; i < g.primitives.size(); ++i) {
            const std::uint64_t before = counts.outside;
            cached.addRecorded(g.primitives[i], &meshes, counts, runs[i]);
            outside[i] = counts.outside - before;
        }
        ASSERT_EQ(cached.countAgainst(target, counts), want) << "model " << model;
        VoxelCounts again;
        for (std::size_t i = 0; i < g.primitives.size(); ++i) {
            cached.replay(runs[i]);
            again.outside += outside[i];
        }
        ASSERT_EQ(withoutWork(cached.countAgainst(target, again)), withoutWork(want)) << "model " << model;
        nonEmpty += want.occupied > 0;
    }
    EXPECT_GT(nonEmpty, 300);
}

TEST(IncrementalScoring, CacheFindsOnlyBitIdenticalPrimitives) {
    PrimitiveCache<RowSpan> cache(1 << 20);
    Primitive p;
    p.kind = PrimitiveKind::Cylinder;
    p.centre = {1.0f, 2.0f, 3.0f};
    const RowSpan rows[2] = {{4, 1, 9}, {5, 2, 8}};
    cache.store(PrimitiveKey(p), PrimitiveKey(p).hash(), rows, 7);
    PrimitiveCache<RowSpan>::Found found;
    ASSERT_TRUE(cache.find(PrimitiveKey(p), PrimitiveKey(p).hash(), found));
    ASSERT_EQ(found.records.size(), 2u);
    EXPECT_EQ(found.records[1].y, 5);
    EXPECT_EQ(found.extra, 7u);
    auto missesFor = [&](Primitive q) {
        const PrimitiveKey key(q);
        return !cache.find(key, key.hash(), found) && !cache.find(key, PrimitiveKey(p).hash(), found);  // even on a colliding hash
    };
    Primitive q = p;
    q.centre.x = std::nextafter(1.0f, 2.0f);
    EXPECT_TRUE(missesFor(q));
    q = p, q.kind = PrimitiveKind::Cone;
    EXPECT_TRUE(missesFor(q));
    q = p, q.params.bytes[KindParams::kBytes - 1] = 1;  // any byte of the kind's parameters, the last one too
    EXPECT_TRUE(missesFor(q));
    q = p, q.params.bytes[0] = 1;
    EXPECT_TRUE(missesFor(q));
    Primitive roof = p;  // two roofs that differ in their z fraction only
    roof.kind = PrimitiveKind::Roof;
    setParams<RoofKind>(roof, {1.0f, 0.25f});
    cache.store(PrimitiveKey(roof), PrimitiveKey(roof).hash(), rows, 7);
    q = roof, setParams<RoofKind>(q, {1.0f, 0.5f});
    EXPECT_TRUE(missesFor(q));
    EXPECT_FALSE(cache.find(PrimitiveKey(q), PrimitiveKey(roof).hash(), found));
    q = p, q.kind = PrimitiveKind::Mesh, setParams<MeshKind>(q, {1});
    EXPECT_TRUE(missesFor(q));
    q = p, q.axes[2][1] = -0.0f;  // equal as a number, not as bits: a miss is always safe
    EXPECT_TRUE(missesFor(q));
    // a primitive that drew nothing is found with no records
    cache.store(PrimitiveKey(q), PrimitiveKey(q).hash(), {}, 0);
    ASSERT_TRUE(cache.find(PrimitiveKey(q), PrimitiveKey(q).hash(), found));
    EXPECT_TRUE(found.records.empty());
}

TEST(IncrementalScoring, OverwrittenRecordsAreMissesNeverWrongRecords) {
    PrimitiveCache<RowSpan> cache(64 * 1024);  // the smallest cache: its ring wraps many times below
    Rng rng(3);
    std::vector<Primitive> prims(3000);
    std::vector<std::vector<RowSpan>> rows(prims.size());
    for (std::size_t i = 0; i < prims.size(); ++i) {
        prims[i].centre = {float(i), 0.0f, 0.0f};
        rows[i].resize(1 + rng.below(40));
        for (RowSpan& r : rows[i]) r = {std::int32_t(i), std::int32_t(rng.below(100)), std::int32_t(rng.below(1000))};
        cache.store(PrimitiveKey(prims[i]), PrimitiveKey(prims[i]).hash(), rows[i], i);
    }
    std::size_t hits = 0;
    PrimitiveCache<RowSpan>::Found found;
    for (std::size_t i = 0; i < prims.size(); ++i) {
        if (!cache.find(PrimitiveKey(prims[i]), PrimitiveKey(prims[i]).hash(), found)) continue;
        ++hits;
        ASSERT_EQ(found.extra, i);
        ASSERT_EQ(found.records.size(), rows[i].size()) << i;
        for (std::size_t r = 0; r < rows[i].size(); ++r) {
            ASSERT_EQ(found.records[r].y, rows[i][r].y) << i;
            ASSERT_EQ(found.records[r].lo, rows[i][r].lo) << i;
            ASSERT_EQ(found.records[r].hi, rows[i][r].hi) << i;
        }
    }
    EXPECT_GT(hits, 50u);                 // the newest are still there
    EXPECT_LT(hits, prims.size() / 2);    // the oldest were overwritten
    EXPECT_LE(cache.bytes(), 64u * 1024);
    EXPECT_EQ(cache.stats().stored, prims.size());
}

TEST(IncrementalScoring, RecordsFoundBeforeAStoreOverwroteThemAreDrawnAgain) {
    // drawThroughCache looks every primitive up before it draws the new ones: a primitive found
    // then, whose records the new ones' stores overwrite, must be drawn again, not replayed.
    PrimitiveCache<RowSpan> cache(64 * 1024);  // a ring of ~4,200 records
    auto rowsOf = [](const Primitive& p, std::vector<RowSpan>& out) {
        const auto id = std::int32_t(p.centre.x);
        for (std::int32_t r = 0; r < (id == 0 ? 10 : 500); ++r) out.push_back({id, r, id + r});
    };
    std::vector<Primitive> prims(10);
    for (std::size_t i = 0; i < prims.size(); ++i) prims[i].centre = {float((i + 1) % prims.size()), 0.0f, 0.0f};
    const Primitive& old = prims.back();  // id 0: stored first, looked up last
    std::vector<RowSpan> rows;
    rowsOf(old, rows);
    cache.store(PrimitiveKey(old), PrimitiveKey(old).hash(), rows, 0);
    PrimitiveCache<RowSpan>::Found found;
    ASSERT_TRUE(cache.find(PrimitiveKey(old), PrimitiveKey(old).hash(), found));
    EXPECT_TRUE(cache.stillHolds(found));
    std::vector<CacheProbe<RowSpan>> probes;
    std::vector<RowSpan> scratch;
    int drawn = 0, replayed = 0;
    auto expectRowsOf = [&](std::span<const RowSpan> got, std::size_t i) {
        std::vector<RowSpan> want;
        rowsOf(prims[i], want);
        ASSERT_EQ(got.size(), want.size()) << i;
        for (std::size_t r = 0; r < want.size(); ++r) ASSERT_EQ(got[r].hi, want[r].hi) << i << " row " << r;
    };
    drawThroughCache(
        cache, prims, probes, scratch, [](const Primitive&, std::size_t) { return false; },
        [&](const PrimitiveCache<RowSpan>::Found& f, std::size_t i) {
            ++replayed;
            expectRowsOf(f.records, i);
        },
        [&](const Primitive& p, std::vector<RowSpan>& out) -> std::uint64_t {
            ++drawn;
            rowsOf(p, out);
            return 0;
        },
        [&](std::span<const RowSpan> got, std::uint64_t, std::size_t i) { expectRowsOf(got, i); });
    EXPECT_FALSE(cache.stillHolds(found));  // the nine new primitives' 4,500 records wrapped the ring
    EXPECT_EQ(drawn, 10);
    EXPECT_EQ(replayed, 0);
}

/// Random trees and their mutated and crossed children (the shape of a GA's stream of models).
std::vector<Chromosome> treesAndChildren(const Grammar& g, std::size_t count) {
    Rng rng(17);
    const GenomeLimits limits{200};
    std::vector<Chromosome> out;
    for (std::size_t i = 0; i < 8; ++i) {
        Chromosome c;
        for (std::uint32_t n = 5 + 3 * std::uint32_t(i); c.genes < n && grow(g, c, rng, limits);) {
        }
        out.push_back(c);
    }
    test::appendChildren(g, out, count, rng, limits, 8, false);
    return out;
}

/// A 160 x 120 target (test::smallTreeCamera's size) of diagonal stripes: a third of it to hit.
ImageTarget stripedTarget() {
    std::vector<std::uint8_t> lum(160 * 120), alpha(160 * 120, 255);
    for (std::size_t i = 0; i < lum.size(); ++i) lum[i] = (i / 160 + i % 160) % 3 ? 255 : 0;
    return makeImageTarget(160, 120, lum, alpha, PixelRule{});
}

TEST(IncrementalScoring, ImageScorerGivesTheSameFitnessAndCountsWithACacheColdOrWarm) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const Camera camera = test::smallTreeCamera();
    const ImageTarget target = stripedTarget();
    ImageScorer full(g, camera, target, FitnessSettings{}), cached(g, camera, target, FitnessSettings{});
    cached.setIncremental(1 << 20, true);  // small: it wraps; checking: any difference throws
    auto wf = full.makeWorkspace(), wc = cached.makeWorkspace();
    auto& c = static_cast<ImageScorer::Workspace&>(*wc);
    ASSERT_TRUE(c.cache.has_value());
    for (const Chromosome& model : treesAndChildren(g, 3000)) {
        SilhouetteCounts a, b;
        const double fa = full.fitness(model, static_cast<ImageScorer::Workspace&>(*wf), &a);
        const double fb = cached.fitness(model, c, &b);
        ASSERT_EQ(fa, fb);
        ASSERT_EQ(a.covered, b.covered);
        ASSERT_EQ(a.hit, b.hit);
    }
    EXPECT_GT(c.cache->stats().hits, c.cache->stats().misses);  // children share most primitives
    EXPECT_GT(c.cache->stats().misses, 1000u);
}

TEST(IncrementalScoring, WholeSubtreesReplayTheirMergedWordsToTheSameCounts) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/tree.grammar"));
    const Camera camera = test::smallTreeCamera();
    std::vector<std::uint8_t> lum(160 * 120), alpha(160 * 120, 255);
    for (std::size_t i = 0; i < lum.size(); ++i) lum[i] = (i / 160 * 7 + i % 160) % 5 ? 255 : 0;
    const ImageTarget target = makeImageTarget(160, 120, lum, alpha, PixelRule{});
    ImageScorer full(g, camera, target, FitnessSettings{}), cached(g, camera, target, FitnessSettings{});
    cached.setIncremental(4 << 20, true);  // checking: any difference throws
    auto wf = full.makeWorkspace(), wc = cached.makeWorkspace();
    auto& c = static_cast<ImageScorer::Workspace&>(*wc);
    Rng rng(5);
    const GenomeLimits limits{300};
    GenomeScratch scratch;
    std::vector<Chromosome> models(4);
    for (Chromosome& m : models) growRandomLength(g, m, rng, limits, 60, 120);
    for (int i = 0; i < 2000; ++i) {
        Chromosome& child = models[rng.below(4)];  // each model walks on by one operator
        if (rng.below(2) == 0) alter(g, child, rng);
        else if (!grow(g, child, rng, limits)) cut(g, child, rng, scratch);
        SilhouetteCounts a, b;
        ASSERT_EQ(full.fitness(child, static_cast<ImageScorer::Workspace&>(*wf), &a), cached.fitness(child, c, &b));
        ASSERT_EQ(a.covered, b.covered);
        ASSERT_EQ(a.hit, b.hit);
    }
    EXPECT_GT(c.subtrees->stats().hits, 1000u);  // whole subtrees replayed at once
    EXPECT_GT(c.derive.memo->stats().hits, 1000u);  // and derived once
}

TEST(IncrementalScoring, AModelLargerThanTheCacheHoldsIsDrawnTheFullWayAndSaidSo) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const Camera camera = test::smallTreeCamera();
    const ImageTarget target = stripedTarget();
    ImageScorer full(g, camera, target, FitnessSettings{}), cached(g, camera, target, FitnessSettings{});
    cached.setIncremental(64 << 10, true);  // the smallest cache: it holds models of a few dozen primitives
    auto wf = full.makeWorkspace(), wc = cached.makeWorkspace();
    auto& f = static_cast<ImageScorer::Workspace&>(*wf);
    auto& c = static_cast<ImageScorer::Workspace&>(*wc);
    Rng rng(4);
    Chromosome small, large;
    growRandomLength(g, small, rng, GenomeLimits{200}, 6, 6);
    growRandomLength(g, large, rng, GenomeLimits{3000}, 1500, 1500);
    SilhouetteCounts a, b;
    derive(g, large, f.geometry, f.derive);
    ASSERT_FALSE(c.cache->holds(f.geometry.primitives.size()));
    derive(g, small, f.geometry, f.derive);
    ASSERT_TRUE(c.cache->holds(f.geometry.primitives.size()));

    EXPECT_EQ(full.fitness(small, f, &a), cached.fitness(small, c, &b));
    EXPECT_EQ(a.covered, b.covered);
    const std::uint64_t lookups = c.cache->stats().hits + c.cache->stats().misses;
    EXPECT_GT(lookups, 0u);
    EXPECT_FALSE(cached.cacheFull());

    EXPECT_EQ(full.fitness(large, f, &a), cached.fitness(large, c, &b));
    EXPECT_EQ(a.covered, b.covered);
    EXPECT_EQ(a.hit, b.hit);
    EXPECT_EQ(c.cache->stats().hits + c.cache->stats().misses, lookups);  // not one lookup
    EXPECT_TRUE(cached.cacheFull());  // said once by the run
}

TEST(IncrementalScoring, AWholeSubtreesKeyHashesAsItsStart) {
    // drawCached takes the start's hash for its key's: the two must never differ.
    Rng rng(5);
    const Appearance look{{0.25f, 0.5f, 1.0f}, 2};
    for (int i = 0; i < 200; ++i) {
        Scope s;
        auto u = [&](double lo, double hi) { return float(lo + (hi - lo) * rng.uniform()); };
        s.origin = {u(-5, 5), u(-5, 5), u(-5, 5)};
        s.size = {u(0, 3), u(0, 3), u(0, 3)};
        s.axes[1][2] = u(-1, 1);
        s.look = rng.below(4);
        const SubtreeMemo::Start start(rng.below(1000000), rng.below(16), nullptr, i % 2 ? &look : nullptr, s);
        EXPECT_EQ(SubtreeKey(start).hash(), start.hash) << i;
    }
}

TEST(IncrementalScoring, CheckingModeStopsOnACacheThatLies) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const Camera camera = test::smallTreeCamera();
    std::vector<std::uint8_t> lum(160 * 120, 0), alpha(160 * 120, 255);
    const ImageTarget target = makeImageTarget(160, 120, lum, alpha, PixelRule{});
    ImageScorer scorer(g, camera, target, FitnessSettings{});
    const Chromosome model = treesAndChildren(g, 8).back();
    Geometry geometry;
    DeriveScratch scratch;
    derive(g, model, geometry, scratch);
    ASSERT_GT(geometry.primitives.size(), 2u);
    for (bool check : {false, true}) {
        scorer.setIncremental(1 << 20, check);
        auto ws = scorer.makeWorkspace();
        auto& w = static_cast<ImageScorer::Workspace&>(*ws);
        const Primitive& lying = geometry.primitives[1];  // say it drew nothing
        w.cache->store(PrimitiveKey(lying), PrimitiveKey(lying).hash(), {}, 0);
        if (check) {
            EXPECT_THROW(scorer.fitness(model, w, nullptr), IncrementalMismatch);
        } else {  // without the check the lie goes through: what the check is there to catch
            SilhouetteCounts lied, truth;
            scorer.fitness(model, w, &lied);
            ImageScorer honest(g, camera, target, FitnessSettings{});
            auto hw = honest.makeWorkspace();
            honest.fitness(model, static_cast<ImageScorer::Workspace&>(*hw), &truth);
            EXPECT_LT(lied.covered, truth.covered);
        }
    }
}

/// n x n x n voxels of 0.1 from `(x, y, z)`.
GridSpec cubeOfVoxels(double x, double y, double z, int n) {
    GridSpec grid;
    grid.origin = {x, y, z};
    grid.voxelSize = 0.1;
    grid.nx = grid.ny = grid.nz = n;
    return grid;
}

TEST(IncrementalScoring, VolumeScorerGivesTheSameCountsWithACacheAndItsCheckCatchesALie) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const GridSpec grid = cubeOfVoxels(-3.0, -0.5, -3.0, 60);
    Rng rng(8);
    const VolumeTarget target = test::randomTarget(grid, rng);
    VolumeScorer full(g, target, FitnessSettings{}), cached(g, target, FitnessSettings{});
    cached.setIncremental(4 << 20, true);
    auto wf = full.makeWorkspace(), wc = cached.makeWorkspace();
    const std::vector<Chromosome> models = treesAndChildren(g, 600);
    for (const Chromosome& model : models) ASSERT_EQ(full.fitness(model, *wf), cached.fitness(model, *wc));
    auto& w = static_cast<VolumeScorer::Workspace&>(*wc);
    EXPECT_GT(w.cache->stats().hits, w.cache->stats().misses);
    // a lie about the last model's first primitive is caught
    Geometry geometry;
    DeriveScratch scratch;
    derive(g, models.back(), geometry, scratch);
    auto fresh = cached.makeWorkspace();
    auto& f = static_cast<VolumeScorer::Workspace&>(*fresh);
    const Primitive& lying = geometry.primitives[0];
    f.cache->store(PrimitiveKey(lying), PrimitiveKey(lying).hash(), {}, 0);
    EXPECT_THROW(cached.fitness(models.back(), f), IncrementalMismatch);
}

TEST(IncrementalScoring, AxisAlignedBoxesAreDrawnDirectlyAndNeverTouchTheCache) {
    // Regression: looking up axis-aligned boxes cost more than drawing them (the spaceship ran
    // 20 % slower with the cache on). They are drawn directly now, with the same counts; a
    // rotated box still goes through the cache.
    Primitive box{};
    box.kind = PrimitiveKind::Box;
    box.half[0] = box.half[1] = box.half[2] = 0.5f;
    for (int k = 0; k < 3; ++k) box.axes[k][k] = 1.0f;
    EXPECT_TRUE(Voxelizer::drawsAsFastAsReplay(box));
    Primitive turned = box;
    turned.axes[0][0] = turned.axes[1][1] = 0.6f, turned.axes[0][1] = 0.8f, turned.axes[1][0] = -0.8f;
    EXPECT_FALSE(Voxelizer::drawsAsFastAsReplay(turned));
    Primitive cylinder = box;
    cylinder.kind = PrimitiveKind::Cylinder;
    EXPECT_FALSE(Voxelizer::drawsAsFastAsReplay(cylinder));

    for (const bool rotated : {false, true}) {
        const std::string text = std::string("start B\nrule B {\n  param s = uniform((0.5, 0.5, 0.5), (1.5, 1.5, 1.5))\n") +
                                 (rotated ? "  rotate y 30\n" : "") +
                                 "  scale s\n  translate (0, 0, parent.size.z * 0.6)\n  box\n  child B prob 0.7 max 2\n}\n";
        const Grammar g = parseGrammar(text, "boxes.grammar");
        const GridSpec grid = cubeOfVoxels(-4.0, -4.0, -2.0, 80);
        Rng rng(3);
        const VolumeTarget target = test::randomTarget(grid, rng);
        VolumeScorer full(g, target, FitnessSettings{}), cached(g, target, FitnessSettings{});
        cached.setIncremental(4 << 20, true);  // checking: a difference throws
        auto wf = full.makeWorkspace(), wc = cached.makeWorkspace();
        for (const Chromosome& model : treesAndChildren(g, 400)) {
            VoxelCounts a, b;
            ASSERT_EQ(full.fitness(model, static_cast<VolumeScorer::Workspace&>(*wf), &a),
                      cached.fitness(model, static_cast<VolumeScorer::Workspace&>(*wc), &b));
            ASSERT_EQ(withoutWork(a), withoutWork(b));
        }
        const auto& stats = static_cast<VolumeScorer::Workspace&>(*wc).cache->stats();
        if (rotated) EXPECT_GT(stats.hits + stats.misses, 1000u) << "rotated boxes are looked up";
        else EXPECT_EQ(stats.hits + stats.misses, 0u) << "axis-aligned boxes are drawn directly";
    }
}

}  // namespace
}  // namespace shapevo
