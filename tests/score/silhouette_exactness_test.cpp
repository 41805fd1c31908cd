// Exact pixel counts: the silhouette rasterizer agrees bit for bit with a brute-force
// point-in-polygon test on 1,000 random primitives per kind (box, cylinder, cone, sphere, mesh)
// and camera (perspective, orthographic, shadow), including primitives partly off-screen,
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
#include <vector>

#include <glm/geometric.hpp>

#include "genome/random.hpp"
#include "score/silhouette_raster.hpp"

namespace shapevo {
namespace {

using Mask = std::vector<std::uint8_t>;

std::int64_t orient(FixedPoint o, FixedPoint a, FixedPoint b) {
    return (std::int64_t(a.x) - o.x) * (std::int64_t(b.y) - o.y) - (std::int64_t(a.y) - o.y) * (std::int64_t(b.x) - o.x);
}

struct BruteStats {
    long onBoundary = 0;  ///< covered pixel centres exactly on a supporting line
    long onSlanted = 0;   ///< ... on one that is neither horizontal nor vertical
};

/// OR the pixels whose centres lie in the closed convex hull of `pts` into `mask` (zero area: none).
void bruteForcePiece(const std::vector<FixedPoint>& pts, int width, int height, Mask& mask, BruteStats& stats) {
    const std::size_t n = pts.size();
    std::vector<std::pair<FixedPoint, FixedPoint>> lines;  // all points on the left of or on a -> b
    bool area = false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (pts[i] == pts[j]) continue;
            bool allLeft = true;
            for (std::size_t k = 0; k < n && allLeft; ++k) {
                const std::int64_t o = orient(pts[i], pts[j], pts[k]);
                if (o != 0) area = true;
                allLeft = o >= 0;
            }
            if (allLeft) lines.push_back({pts[i], pts[j]});
        }
    if (!area) return;
    std::int64_t x0 = INT64_MAX, x1 = INT64_MIN, y0 = INT64_MAX, y1 = INT64_MIN;
    for (const FixedPoint& p : pts) {
        x0 = std::min<std::int64_t>(x0, p.x), x1 = std::max<std::int64_t>(x1, p.x);
        y0 = std::min<std::int64_t>(y0, p.y), y1 = std::max<std::int64_t>(y1, p.y);
    }
    // pixel i has its centre at 256 i + 128; only centres inside the bounding box can be inside
    const std::int64_t i0 = std::max<std::int64_t>(0, (x0 - 128) / 256 - 1), i1 = std::min<std::int64_t>(width - 1, (x1 - 128) / 256 + 1);
    const std::int64_t j0 = std::max<std::int64_t>(0, (y0 - 128) / 256 - 1), j1 = std::min<std::int64_t>(height - 1, (y1 - 128) / 256 + 1);
    for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i) {
            const FixedPoint c{std::int32_t(256 * i + 128), std::int32_t(256 * j + 128)};
            bool inside = true, edge = false, slanted = false;
            for (const auto& [a, b] : lines) {
                const std::int64_t o = orient(a, b, c);
                if (o < 0) {
                    inside = false;
                    break;
                }
                edge = edge || o == 0;
                slanted = slanted || (o == 0 && a.x != b.x && a.y != b.y);
            }
            if (inside) {
                mask[std::size_t(j) * std::size_t(width) + std::size_t(i)] = 1;
                stats.onBoundary += edge;
                stats.onSlanted += slanted;
            }
        }
}

void bruteForce(const Primitive& p, const std::vector<MeshShape>& meshes, OutlineBuilder& builder, int width, int height,
                Mask& mask, BruteStats& stats) {
    Outline outline;
    builder.add(p, &meshes, outline);
    for (const OutlinePiece& piece : outline.pieces) {
        const std::vector<FixedPoint> pts(outline.points.begin() + piece.first, outline.points.begin() + piece.first + piece.count);
        bruteForcePiece(pts, width, height, mask, stats);
    }
}

/// A closed, concave mesh in unit coordinates: a five-pointed star extruded along y.
std::vector<MeshShape> starMesh() {
    MeshShape m;
    m.path = "star";
    for (int y : {-1, 1}) {
        m.vertices.push_back({0.0f, float(y), 0.0f});
        for (int k = 0; k < 10; ++k) {
            const double a = M_PI * k / 5.0, r = k % 2 ? 0.4 : 1.0;
            m.vertices.push_back({float(r * std::cos(a)), float(y), float(r * std::sin(a))});
        }
    }
    for (std::uint32_t k = 0; k < 10; ++k) {
        const std::uint32_t a = 1 + k, b = 1 + (k + 1) % 10;
        m.triangles.push_back({0, b, a});            // bottom cap
        m.triangles.push_back({11, 11 + a, 11 + b});  // top cap
        m.triangles.push_back({a, b, 11 + b});        // side
        m.triangles.push_back({a, 11 + b, 11 + a});
    }
    return {m};
}

glm::mat3 randomRotation(Rng& rng) {
    double q[4], n = 0;
    for (double& v : q) v = rng.normal(), n += v * v;
    n = std::sqrt(n);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                            {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                            {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
    glm::mat3 r;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) r[c][k] = float(m[c][k]);
    return r;
}

struct Scene {
    const char* name;
    CameraSpec spec;
    glm::dvec3 centre;  ///< where the camera looks: primitives are placed around it
    double extent;      ///< half size of the region primitives are placed in
    glm::dvec3 nearPoint;  ///< a point on the near plane / the ground, for crossing primitives
};

std::vector<Scene> scenes() {
    std::vector<Scene> s;
    CameraSpec p;
    p.width = 200, p.height = 150;
    p.eye = {6.0, 5.0, 7.0}, p.lookAt = {0.0, 0.5, 0.0}, p.up = {0.1, 1.0, 0.0}, p.fovDegrees = 50.0, p.near = 0.5;
    const glm::dvec3 f = glm::normalize(p.lookAt - p.eye);
    s.push_back({"perspective", p, p.lookAt, 6.0, p.eye + p.near * f});
    CameraSpec o = p;
    o.projection = Projection::Orthographic;
    o.viewHeight = 9.0;
    s.push_back({"orthographic", o, o.lookAt, 6.0, o.eye + o.near * f});
    CameraSpec h;
    h.projection = Projection::Shadow;
    h.width = 200, h.height = 150;
    h.light = {0.4, -1.0, 0.3}, h.groundY = -2.0, h.groundMin = {-6.0, -6.0}, h.groundMax = {6.0, 6.0};
    s.push_back({"shadow", h, {0.0, 0.0, 0.0}, 6.0, {0.0, -2.0, 0.0}});
    return s;
}

Primitive randomPrimitive(PrimitiveKind kind, const Scene& scene, Rng& rng) {
    Primitive p;
    p.kind = kind;
    const int style = int(rng.below(10));
    glm::dvec3 c = scene.centre;
    for (int k = 0; k < 3; ++k) c[k] += scene.extent * (2.0 * rng.uniform() - 1.0);
    if (style == 0) c = scene.nearPoint + 1.5 * glm::dvec3(rng.normal(), rng.normal(), rng.normal());  // crosses the plane
    if (style == 1) c.x += (rng.below(2) ? 1 : -1) * 3.0 * scene.extent;                              // mostly off-screen
    p.centre = glm::vec3(c);
    for (int k = 0; k < 3; ++k) p.half[k] = float(0.02 * std::pow(150.0, rng.uniform()));  // 0.02 .. 3
    if (style == 2) p.half[int(rng.below(3))] = 0.0f;                                       // flat
    if (style == 3) p.half *= 20.0f;                                                         // huge: reaches the guard band
    p.axes = style == 4 ? glm::mat3(1.0f) : randomRotation(rng);
    if (rng.below(4) == 0) p.axes[int(rng.below(3))] *= -1.0f;  // mirrored
    const std::uint32_t t = rng.below(10);
    p.taper = t == 0 ? 0.0f : t == 1 ? 1.0f : float(rng.uniform());
    p.mesh = 0;
    return p;
}

/// Boxes whose corners project exactly onto pixel centres and pixel edges (orthographic, 16 px per unit).
Primitive alignedBox(Rng& rng) {
    Primitive p;
    p.kind = PrimitiveKind::Box;
    p.centre = glm::vec3(float(int(rng.below(200)) - 100) / 32.0f, float(int(rng.below(150)) - 75) / 32.0f, 0.0f);
    p.half = glm::vec3(float(1 + rng.below(64)) / 32.0f, float(1 + rng.below(64)) / 32.0f, 0.5f);
    return p;
}

ImageTarget randomTarget(int width, int height, Rng& rng) {
    std::vector<std::uint8_t> lum(std::size_t(width) * height), alpha(lum.size(), 255);
    for (std::size_t i = 0; i < lum.size(); ++i) {
        const double u = rng.uniform();
        lum[i] = u < 0.4 ? 0 : u < 0.8 ? 255 : 128;
        alpha[i] = u < 0.9 ? 255 : 0;
    }
    PixelRule rule;
    rule.hitMax = 100, rule.avoidMin = 200;  // 128 = don't care
    return makeImageTarget(width, height, lum, alpha, rule);
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
    const char* names[] = {"box", "cylinder", "cone", "sphere", "mesh"};
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
                                  << ") half (" << p.half.x << ", " << p.half.y << ", " << p.half.z << ") taper " << p.taper;
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
