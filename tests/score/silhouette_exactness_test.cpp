// Exact pixel counts: the silhouette rasterizer agrees bit for bit with a brute-force
// point-in-polygon test on 1,000 random primitives per kind (box, cylinder, cone, sphere, mesh,
// roof with ridges, apexes and square frusta, paraboloid) and camera (perspective, orthographic, shadow), including primitives partly off-screen,
// crossing the near plane / the ground, flat or huge, mirrored, and boundary-aligned boxes whose
// corners land exactly on pixel centres. Also the counts against a random target, and unions.
//
// The brute force shares only the outline points (silhouette_outline.hpp: which points the
// silhouette is the hull of). It does not build a hull at all: a pixel centre is inside the
// closed convex hull of a point set exactly when it lies on the inner side of every line through
// two of the points that has all points on one side, tested with exact integers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "silhouette_test_util.hpp"
#include "../kind_params.hpp"

namespace shapevo {
namespace {

using namespace test;

/// Boxes whose corners project exactly onto pixel centres and pixel edges (orthographic, 16 px per unit).
Primitive alignedBox(Rng& rng) {
    Primitive p;
    p.kind = PrimitiveKind::Box;
    p.centre = glm::vec3(float(int(rng.below(200)) - 100) / 32.0f, float(int(rng.below(150)) - 75) / 32.0f, 0.0f);
    p.half = glm::vec3(float(1 + rng.below(64)) / 32.0f, float(1 + rng.below(64)) / 32.0f, 0.5f);
    return p;
}

SilhouetteCounts countMask(const Mask& mask, const ImageTarget& t) {
    SilhouetteCounts c;
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x)
            if (mask[std::size_t(y) * std::size_t(t.width) + std::size_t(x)]) {
                ++c.covered;
                c.hit += t.isHit(x, y);
                c.avoided += t.isAvoid(x, y);
            }
    return c;
}

/// Compare drawing `prims` (one model) with the brute force; returns false on the first mismatch.
bool agrees(SilhouetteRaster& raster, OutlineBuilder& builder, const std::vector<Primitive>& prims,
            const std::vector<MeshShape>& meshes, const ImageTarget& target, BruteStats& stats, long& coveredTotal) {
    const int w = target.width, h = target.height;
    Mask expected(std::size_t(w) * h, 0), got;
    for (const Primitive& p : prims) {
        raster.add(p, &meshes);
        bruteForce(p, meshes, builder, w, h, expected, stats);
    }
    raster.fillMask(got);
    SilhouetteCounts counts = raster.score(target);
    counts.rows = 0;
    if (got != expected) {
        std::size_t diff = 0, first = 0;
        for (std::size_t i = 0; i < got.size(); ++i)
            if (got[i] != expected[i] && diff++ == 0) first = i;
        ADD_FAILURE() << diff << " pixels differ, first at (" << first % w << ", " << first / w << "): raster "
                      << int(got[first]) << ", brute force " << int(expected[first]);
        return false;
    }
    const SilhouetteCounts want = countMask(expected, target);
    EXPECT_EQ(counts, want);
    coveredTotal += long(want.covered);
    return counts == want;
}

const char* kindName(PrimitiveKind k) {
    const char* names[] = {"box", "cylinder", "cone", "sphere", "mesh", "roof", "paraboloid"};
    static_assert(std::size(names) == kPrimitiveKinds);
    return names[int(k)];
}

TEST(SilhouetteExactness, EveryKindAndCameraMatchesBruteForceBitForBit) {
    const std::vector<MeshShape> meshes = starMesh();
    for (const Scene& scene : scenes()) {
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        OutlineBuilder builder(camera);
        Rng rng(7);
        const ImageTarget target = randomTarget(camera.width(), camera.height(), rng);
        for (int k = 0; k < kPrimitiveKinds; ++k) {
            const auto kind = PrimitiveKind(k);
            SCOPED_TRACE(std::string(scene.name) + " " + kindName(kind));
            BruteStats stats;
            long covered = 0, crossing = 0, empty = 0;
            for (int i = 0; i < 1000; ++i) {
                const Primitive p = randomPrimitive(kind, scene, rng);
                crossing += !camera.visible(glm::dvec3(p.centre));
                const long before = covered;
                if (!agrees(raster, builder, {p}, meshes, target, stats, covered)) {
                    ADD_FAILURE() << "primitive " << i << " centre (" << p.centre.x << ", " << p.centre.y << ", " << p.centre.z
                                  << ") half (" << p.half.x << ", " << p.half.y << ", " << p.half.z << ") taper " << test::taperOf(p)
                                  << " taperZ " << test::taperZOf(p);
                    return;
                }
                empty += covered == before;
            }
            // the cases the test is meant to cover did occur
            EXPECT_GT(crossing, 30);          // centres behind the near plane / below the ground
            EXPECT_GT(empty, 20);             // nothing visible (off-screen, behind, flat)
            EXPECT_LT(empty, 700);
            EXPECT_GT(covered, 100000);
        }
    }
}

TEST(SilhouetteExactness, PixelCentresExactlyOnEdgesAndCornersAreCovered) {
    CameraSpec spec;
    spec.projection = Projection::Orthographic;
    spec.width = 200, spec.height = 150;
    spec.eye = {0.0, 0.0, 10.0};
    spec.viewHeight = 150.0 / 16.0;  // 16 pixels per unit: x = 100 + 16 X, y = 75 - 16 Y
    const Camera camera = Camera::compile(spec, "test");
    SilhouetteRaster raster(camera);
    OutlineBuilder builder(camera);
    Rng rng(11);
    const ImageTarget target = randomTarget(200, 150, rng);
    const std::vector<MeshShape> meshes;
    BruteStats stats;
    long covered = 0;
    for (int i = 0; i < 1000; ++i) {
        Primitive p = alignedBox(rng);
        if (i % 2) p.axes = glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1);  // a quarter turn: still aligned
        ASSERT_TRUE(agrees(raster, builder, {p}, meshes, target, stats, covered)) << "box " << i;
    }
    EXPECT_GT(stats.onBoundary, 1000);  // edges through pixel centres really happened
    // a box from pixel centre to pixel centre covers both end columns: (x1 - x0 + 1) columns
    Primitive p;
    p.centre = {0.5f / 16.0f, 0.5f / 16.0f, 0.0f};  // corners at pixel centres 90.5 / 110.5 and 64.5 / 84.5
    p.half = {10.0f / 16.0f, 10.0f / 16.0f, 1.0f};
    raster.add(p, nullptr);
    EXPECT_EQ(raster.score(target).covered, 21u * 21u);
}

/// Triangles with vertices on the lattice u = k / 16: with the 16 px per unit camera below and a
/// centre at ((2a + 1) / 32, (2b + 1) / 32) every vertex lands on a pixel centre, and slanted
/// edges pass exactly through further pixel centres (where a rounding rasterizer goes wrong).
std::vector<MeshShape> latticeSoup(Rng& rng) {
    MeshShape m;
    m.path = "lattice";
    for (std::uint32_t t = 0; t < 40; ++t) {
        const glm::vec3 a(float(int(rng.below(33)) - 16) / 16.0f, float(int(rng.below(33)) - 16) / 16.0f, 0.0f);
        for (int k = 0; k < 3; ++k) {
            const int dx = int(rng.below(13)) - 6, dy = int(rng.below(13)) - 6;
            m.vertices.push_back({std::clamp(a.x + float(dx) / 16.0f, -1.0f, 1.0f), std::clamp(a.y + float(dy) / 16.0f, -1.0f, 1.0f),
                                  float(int(rng.below(33)) - 16) / 16.0f});
        }
        m.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    return {m};
}

TEST(SilhouetteExactness, PixelCentresExactlyOnSlantedEdgesAreCovered) {
    CameraSpec spec;
    spec.projection = Projection::Orthographic;
    spec.width = 200, spec.height = 150;
    spec.eye = {0.0, 0.0, 10.0};
    spec.viewHeight = 150.0 / 16.0;
    const Camera camera = Camera::compile(spec, "test");
    SilhouetteRaster raster(camera);
    OutlineBuilder builder(camera);
    Rng rng(5);
    const ImageTarget target = randomTarget(200, 150, rng);
    BruteStats stats;
    long covered = 0;
    for (int i = 0; i < 300; ++i) {
        const std::vector<MeshShape> meshes = latticeSoup(rng);
        Primitive p;
        p.kind = PrimitiveKind::Mesh;
        p.centre = glm::vec3(float(2 * int(rng.below(120)) - 119) / 32.0f, float(2 * int(rng.below(90)) - 89) / 32.0f, 0.0f);
        p.half = glm::vec3(float(1 + rng.below(3)));
        if (i % 3 == 1) p.axes = glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1);  // quarter turn
        if (i % 3 == 2) p.axes[0] = -p.axes[0];                         // mirrored
        ASSERT_TRUE(agrees(raster, builder, {p}, meshes, target, stats, covered)) << "soup " << i;
    }
    EXPECT_GT(stats.onSlanted, 1000);
}

TEST(SilhouetteExactness, ExtremeAndBrokenPrimitivesStayExactOrDrawNothing) {
    const std::vector<MeshShape> meshes = starMesh();
    const float huge = 1e30f, tiny = 1e-30f, inf = INFINITY, nan = NAN;
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        OutlineBuilder builder(camera);
        Rng rng(13);
        const ImageTarget target = randomTarget(camera.width(), camera.height(), rng);
        BruteStats stats;
        long covered = 0;
        for (int k = 0; k < kPrimitiveKinds; ++k)
            for (int i = 0; i < 60; ++i) {
                Primitive p = randomPrimitive(PrimitiveKind(k), scene, rng);
                switch (i % 6) {
                case 0: p.half *= huge; break;                  // covers everything or is cut everywhere
                case 1: p.half *= tiny; break;                  // a point
                case 2: p.centre[int(rng.below(3))] = (rng.below(2) ? 1 : -1) * huge; break;
                case 3: p.centre.x += 1e4f * float(rng.normal()); break;  // beyond the guard band
                case 4: p.half[int(rng.below(3))] = rng.below(2) ? inf : nan; break;
                case 5: p.axes[int(rng.below(3))][int(rng.below(3))] = nan; break;
                }
                ASSERT_TRUE(agrees(raster, builder, {p}, meshes, target, stats, covered)) << "kind " << k << " case " << i;
            }
        EXPECT_GT(covered, 0);
    }
}

TEST(SilhouetteExactness, UnionsOfPrimitivesMatchBruteForce) {
    const std::vector<MeshShape> meshes = starMesh();
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        OutlineBuilder builder(camera);
        Rng rng(3);
        const ImageTarget target = randomTarget(camera.width(), camera.height(), rng);
        BruteStats stats;
        long covered = 0;
        for (int m = 0; m < 100; ++m) {
            std::vector<Primitive> model;
            for (int i = 0; i < 8; ++i) model.push_back(randomPrimitive(PrimitiveKind(rng.below(kPrimitiveKinds)), scene, rng));
            ASSERT_TRUE(agrees(raster, builder, model, meshes, target, stats, covered)) << "model " << m;
        }
    }
}

}  // namespace
}  // namespace shapevo
