// Silhouettes are the right shapes (the exactness test only shows the raster matches its own
// outline points): the silhouette vertices of boxes, cylinders, cones and roofs span the hull of
// all their vertices, and paraboloids draw the hull of their polyhedron's vertices (all projected
// independently here); spheres lie inside their exact outline and fill
// nearly all of it; a mesh cube draws like a box; the near plane and the ground cut primitives;
// shadows land where the light sends them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "silhouette_test_util.hpp"
#include "../kind_params.hpp"

namespace shapevo {
namespace {

using namespace test;

/// All vertices of a box / prism / frustum / pyramid / roof / paraboloid polyhedron in local
/// coordinates, from the definitions in shape/primitive.hpp and silhouette_outline.hpp (not from
/// the outline code).
std::vector<glm::dvec3> allVertices(const Primitive& p) {
    std::vector<glm::dvec3> v;
    if (p.kind == PrimitiveKind::Box) {
        for (int i = 0; i < 8; ++i) v.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
        return v;
    }
    if (p.kind == PrimitiveKind::Roof) {  // the bottom square and the top rectangle
        const double tx = std::clamp(double(test::taperOf(p)), 0.0, 1.0), tz = std::clamp(double(test::taperZOf(p)), 0.0, 1.0);
        for (int i = 0; i < 8; ++i) {
            const double s = i & 2 ? 1.0 : -1.0;
            v.push_back({(i & 1 ? 1.0 : -1.0) * (s > 0 ? tx : 1.0), s, (i & 4 ? 1.0 : -1.0) * (s > 0 ? tz : 1.0)});
        }
        return v;
    }
    if (p.kind == PrimitiveKind::Paraboloid) {  // rings at radii 1, 3/4, 1/2, 1/4 on u.y = 1 - 2 r^2, the apex
        for (int i = 0; i < 4; ++i) {
            const double r = 1.0 - i / 4.0;
            for (int k = 0; k < kRoundSides; ++k) {
                const double a = 2.0 * M_PI * k / kRoundSides;
                v.push_back({r * std::cos(a), 1.0 - 2.0 * r * r, r * std::sin(a)});
            }
        }
        v.push_back({0.0, 1.0, 0.0});
        return v;
    }
    const double top = p.kind == PrimitiveKind::Cone ? std::max(0.0, double(test::taperOf(p))) : 1.0;
    for (int k = 0; k < kRoundSides; ++k) {
        const double a = 2.0 * M_PI * k / kRoundSides;
        v.push_back({std::cos(a), -1.0, std::sin(a)});
        if (top > 0.0) v.push_back({top * std::cos(a), 1.0, top * std::sin(a)});
    }
    if (top == 0.0) v.push_back({0.0, 1.0, 0.0});
    return v;
}

glm::dvec3 world(const Primitive& p, const glm::dvec3& u) {
    glm::dvec3 w(p.centre);
    for (int k = 0; k < 3; ++k) w += glm::dvec3(p.axes[k]) * (double(p.half[k]) * u[k]);
    return w;
}

// Full detail: the drawing equals the hull of all vertices up to rounding (pixel centres within
// 1/64 pixel of its edges). Fewer corners (small rings, silhouette_outline.hpp): the drawing lies
// inside that hull and misses only pixel centres within 1/4 pixel of its edges.
TEST(SilhouetteGeometry, SilhouetteVerticesSpanTheHullOfAllVertices) {
    for (const Scene& scene : scenes()) {
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        OutlineBuilder builder(camera);
        Outline outline;
        const int w = camera.width(), h = camera.height();
        Rng rng(21);
        for (PrimitiveKind kind : {PrimitiveKind::Box, PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Roof,
                                   PrimitiveKind::Paraboloid}) {
            const bool detailLevels = kind == PrimitiveKind::Cylinder || kind == PrimitiveKind::Cone;
            SCOPED_TRACE(std::string(scene.name) + " kind " + std::to_string(int(kind)));
            long compared = 0, exact = 0, reduced = 0;
            for (int i = 0; i < 1000; ++i) {
                const Primitive p = randomPrimitive(kind, scene, rng);
                std::vector<FixedPoint> pts;
                bool usable = true;
                for (const glm::dvec3& u : allVertices(p)) {
                    const glm::dvec3 q = world(p, u);
                    const glm::dvec2 s = camera.project(q);
                    usable = usable && camera.visible(q) && std::fabs(s.x) < 10000 && std::fabs(s.y) < 10000;
                    pts.push_back(snapToFixed(s.x, s.y));
                }
                if (!usable) continue;  // cut or far off: every vertex is kept anyway
                outline.clear();
                builder.add(p, nullptr, outline);
                const bool full = builder.lastRoundPoints() == 0 || builder.lastRoundPoints() == kRoundSides;
                if (!detailLevels) {
                    ASSERT_EQ(builder.lastRoundPoints(), 0);
                }
                Mask expected(std::size_t(w) * h, 0), got;
                BruteStats stats;
                bruteForcePiece(pts, w, h, expected, stats);
                raster.add(p, nullptr);
                raster.fillMask(got);
                raster.clear();
                std::vector<Line> lines;
                supportingLines(pts, lines);
                (full ? compared : reduced) += 1;
                exact += full && got == expected;
                for (std::size_t k = 0; k < got.size(); ++k)
                    if (got[k] != expected[k]) {
                        const FixedPoint c{std::int32_t(256 * (k % w) + 128), std::int32_t(256 * (k / w) + 128)};
                        // extra pixels only from rounding; missing ones up to 1/4 pixel (64 units) inside
                        const double allowed = full || got[k] ? 4.0 : 68.0;
                        ASSERT_LT(distanceToBoundary(lines, c), allowed) << "primitive " << i << " pixel " << k % w << "," << k / w;
                    }
            }
            EXPECT_GT(compared, detailLevels ? 150 : 500);
            EXPECT_GE(exact, compared - 5);  // rounding-level differences are rare
            if (detailLevels) {
                EXPECT_GT(reduced, 50);
            }
            std::printf("%s kind %d: %ld full detail, %ld fewer corners\n", scene.name, int(kind), compared, reduced);
        }
    }
}

/// Does the ray o + t d (t > 0 if `forward`) meet the ellipsoid of p scaled by `scale`?
bool rayHits(const Primitive& p, glm::dvec3 o, glm::dvec3 d, double scale, bool forward) {
    glm::dvec3 lo, ld;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 axis(p.axes[k]);
        lo[k] = glm::dot(axis, o - glm::dvec3(p.centre)) / (scale * p.half[k]);
        ld[k] = glm::dot(axis, d) / (scale * p.half[k]);
    }
    const double a = glm::dot(ld, ld), b = glm::dot(lo, ld), c = glm::dot(lo, lo) - 1.0;
    const double disc = b * b - a * c;
    if (disc < 0) return false;
    return !forward || (-b + std::sqrt(disc)) / a > 0;
}

TEST(SilhouetteGeometry, SpheresFillTheirExactOutlineFromInside) {
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        const Camera camera = Camera::compile(scene.spec, "test");
        SilhouetteRaster raster(camera);
        const CameraSpec& s = scene.spec;
        const int w = camera.width(), h = camera.height();
        const glm::dvec3 f = glm::normalize(s.lookAt - s.eye), r = glm::normalize(glm::cross(f, s.up)), up = glm::cross(r, f);
        const double focal = 0.5 * h / std::tan(0.5 * s.fovDegrees * M_PI / 180.0), perUnit = h / s.viewHeight;
        auto ray = [&](double x, double y, glm::dvec3& o, glm::dvec3& d) {  // through pixel position (x, y)
            switch (s.projection) {
            case Projection::Perspective: o = s.eye, d = f + ((x - 0.5 * w) / focal) * r - ((y - 0.5 * h) / focal) * up; break;
            case Projection::Orthographic: o = s.eye + ((x - 0.5 * w) / perUnit) * r - ((y - 0.5 * h) / perUnit) * up, d = f; break;
            case Projection::Shadow:
                o = {camera.groundMin().x + x / w * (camera.groundMax().x - camera.groundMin().x), s.groundY,
                     camera.groundMin().y + y / h * (camera.groundMax().y - camera.groundMin().y)};  // the rectangle used
                d = -s.light;
                break;
            }
        };
        Rng rng(8);
        int tested = 0;
        for (int i = 0; i < 400 && tested < 150; ++i) {
            Primitive p = randomPrimitive(PrimitiveKind::Sphere, scene, rng);
            if (p.half.x == 0 || p.half.y == 0 || p.half.z == 0) continue;
            bool inFront = true;  // the ellipsoid's bounding box in front of the near plane / above the ground
            for (int c = 0; c < 8; ++c) inFront = inFront && camera.visible(world(p, {c & 1 ? 1. : -1., c & 2 ? 1. : -1., c & 4 ? 1. : -1.}));
            if (!inFront) continue;
            raster.add(p, nullptr);
            Mask got;
            raster.fillMask(got);
            raster.clear();
            long hits = 0, covered = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    glm::dvec3 o, d;
                    ray(x + 0.5, y + 0.5, o, d);
                    const bool in = got[std::size_t(y) * w + x];
                    hits += rayHits(p, o, d, 1.0, s.projection == Projection::Perspective);
                    covered += in;
                    if (in) {
                        ASSERT_TRUE(rayHits(p, o, d, 1.01, s.projection == Projection::Perspective)) << i << ": " << x << "," << y;
                    }
                }
            if (hits >= 300) {
                ++tested;
                EXPECT_GE(double(covered), 0.97 * double(hits)) << "sphere " << i;
            }
        }
        EXPECT_GT(tested, 40);
    }
}

TEST(SilhouetteGeometry, MeshCubeDrawsLikeABox) {
    MeshShape cube;
    for (int i = 0; i < 8; ++i) cube.vertices.push_back({i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f});
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) cube.triangles.push_back({q[0], q[1], q[2]}), cube.triangles.push_back({q[0], q[2], q[3]});
    const std::vector<MeshShape> meshes{cube};
    const Scene scene = scenes()[0];
    const Camera camera = Camera::compile(scene.spec, "test");
    SilhouetteRaster raster(camera);
    Rng rng(4);
    long differing = 0, covered = 0;
    for (int i = 0; i < 300; ++i) {
        Primitive box = randomPrimitive(PrimitiveKind::Box, scene, rng), mesh = box;
        mesh.kind = PrimitiveKind::Mesh;
        Mask a, b;
        raster.add(box, &meshes);
        raster.fillMask(a);
        raster.clear();
        raster.add(mesh, &meshes);
        raster.fillMask(b);
        covered += raster.score(randomTarget(camera.width(), camera.height(), rng)).covered;
        for (std::size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k];
    }
    EXPECT_GT(covered, 100000);
    EXPECT_LE(differing, 3);  // only pixel centres within rounding of an edge may differ
}

TEST(SilhouetteGeometry, NearPlaneCutsAndSurroundsAsExpected) {
    CameraSpec spec;  // eye (0, 0, 10) looking down -z, near 0.1
    spec.width = 160, spec.height = 120;
    const Camera camera = Camera::compile(spec, "test");
    SilhouetteRaster raster(camera);
    Rng rng(1);
    const ImageTarget target = randomTarget(160, 120, rng);
    for (PrimitiveKind kind : {PrimitiveKind::Box, PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Sphere}) {
        Primitive around;  // the eye inside: everything is covered
        around.kind = kind;
        around.centre = {0.0f, 0.0f, 10.0f};
        around.half = glm::vec3(kind == PrimitiveKind::Box ? 1.0f : 3.0f);
        raster.add(around, nullptr);
        EXPECT_EQ(raster.score(target).covered, 160u * 120u) << int(kind);
        Primitive behind = around;  // wholly behind the eye: nothing
        behind.centre.z = 14.0f;
        behind.half = glm::vec3(1.0f);
        raster.add(behind, nullptr);
        EXPECT_EQ(raster.score(target).covered, 0u) << int(kind);
    }
    // A long box from behind the eye to z = 0 draws like the box from the near plane to z = 0.
    Primitive longBox;
    longBox.centre = {1.3f, -0.2f, 6.0f};  // beside the eye
    longBox.half = {0.5f, 0.4f, 6.0f};  // z in [0, 12]; the near plane is at z = 9.9
    Primitive cutBox = longBox;
    cutBox.centre.z = 4.95f;
    cutBox.half.z = 4.95f;  // z in [0, 9.9]
    Mask a, b;
    raster.add(longBox, nullptr);
    raster.fillMask(a);
    raster.clear();
    raster.add(cutBox, nullptr);
    raster.fillMask(b);
    raster.clear();
    long differing = 0, covered = 0;
    for (std::size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k], covered += a[k];
    EXPECT_GT(covered, 1000);
    EXPECT_LE(differing, 2);
}

TEST(SilhouetteGeometry, ShadowsFallAlongTheLightAndOnlyFromAboveTheGround) {
    CameraSpec spec;
    spec.projection = Projection::Shadow;
    spec.width = 200, spec.height = 100;
    spec.groundY = 0.0, spec.groundMin = {-10.0, -5.0}, spec.groundMax = {10.0, 5.0};  // 10 px per unit
    spec.light = {0.0, -1.0, 0.0};
    const Camera straight = Camera::compile(spec, "test");
    SilhouetteRaster raster(straight);
    Rng rng(2);
    const ImageTarget target = randomTarget(200, 100, rng);
    Primitive box;  // footprint x in [-2, 2], z in [-1, 1]: 40 x 20 pixel centres
    box.centre = {0.0f, 1.0f, 0.0f};
    box.half = {2.0f, 1.0f, 1.0f};
    raster.add(box, nullptr);
    EXPECT_EQ(raster.score(target).covered, 40u * 20u);
    box.centre.y = -0.5f;  // half below the ground: the same footprint
    raster.add(box, nullptr);
    EXPECT_EQ(raster.score(target).covered, 40u * 20u);
    box.centre.y = -1.5f;  // wholly below: no shadow
    raster.add(box, nullptr);
    EXPECT_EQ(raster.score(target).covered, 0u);
    // A slanted light moves the shadow of a raised block by height * (L.x / -L.y).
    spec.light = {1.0, -2.0, 0.0};
    const Camera slanted = Camera::compile(spec, "test");
    SilhouetteRaster shifted(slanted);
    Primitive slab;  // a thin slab at height 4, footprint 2 x 2: its shadow is 2 units to +x
    slab.centre = {0.0f, 4.0f, 0.0f};
    slab.half = {1.0f, 0.001f, 1.0f};
    shifted.add(slab, nullptr);
    Mask m;
    shifted.fillMask(m);
    long count = 0, sumX = 0;
    for (std::size_t k = 0; k < m.size(); ++k)
        if (m[k]) ++count, sumX += long(k % 200);
    EXPECT_EQ(count, 20 * 20);
    EXPECT_DOUBLE_EQ(double(sumX) / double(count), 100.0 + 10.0 * 2.0 - 0.5);  // columns 110 .. 129
}

}  // namespace
}  // namespace shapevo
