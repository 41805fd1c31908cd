// Tessellation: every primitive kind becomes a closed, outward-facing surface whose vertices lie
// on the kind's solid as primitive.hpp defines it, in plain, rotated and mirrored frames (roofs
// with ridge and apex tops too, without zero-area triangles); meshOf uses it for whole models.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/tessellation.hpp"
#include "report/model_writer.hpp"
#include "shape/kinds/paraboloid.hpp"

#include "../kind_params.hpp"

namespace shapevo {
namespace {

constexpr double kPi = std::numbers::pi;

/// Each directed edge must appear exactly once and its reverse exactly once: closed (every edge
/// shared by two triangles) and consistently wound. Returns the number of bad edges.
int badEdges(const Mesh& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : m.triangles)
        for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
    int bad = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
    }
    return bad;
}

/// Volume enclosed by the triangles; positive when they face outwards.
double signedVolume(const Mesh& m) {
    double v = 0;
    for (const auto& t : m.triangles) {
        const glm::dvec3 a(m.vertices[t[0]]), b(m.vertices[t[1]]), c(m.vertices[t[2]]);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

/// Area of the regular kRoundSides-gon inscribed in the unit circle.
double polygonArea() { return 0.5 * kRoundSides * std::sin(2.0 * kPi / kRoundSides); }

Primitive primitive(PrimitiveKind kind, const glm::mat3& axes, float taper = 1.0f) {
    Primitive p;
    p.kind = kind;
    test::setKindParams(p, taper);
    p.centre = {3.0f, -1.0f, 2.5f};
    p.axes = axes;
    p.half = {1.5f, 0.75f, 2.0f};
    return p;
}

struct Frame {
    const char* name;
    glm::mat3 axes;
};

std::vector<Frame> frames() {
    const glm::mat3 rotated = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, -0.5f))));
    glm::mat3 mirrored = rotated;
    mirrored[1] = -mirrored[1];  // `mirror y` flips one axis: det = -1
    glm::mat3 mirroredX(1.0f);
    mirroredX[0] = -mirroredX[0];
    return {{"identity", glm::mat3(1.0f)}, {"rotated", rotated}, {"mirrored", mirrored}, {"mirrored x", mirroredX}};
}

/// A vertex's unit coordinates u: world = centre + axes * (half * u).
glm::vec3 unitCoordinates(const Primitive& p, const glm::vec3& world) {
    return glm::inverse(p.axes) * (world - p.centre) / p.half;
}

Mesh surface(const Primitive& p, const std::vector<MeshShape>* meshes = nullptr) {
    Mesh m;
    appendSurface(p, meshes, m);
    return m;
}

double boxVolume(const Primitive& p) { return 8.0 * p.half.x * p.half.y * p.half.z; }

TEST(Tessellation, BoxIsClosedOutwardAndExactInEveryFrame) {
    for (const Frame& f : frames()) {
        SCOPED_TRACE(f.name);
        const Primitive p = primitive(PrimitiveKind::Box, f.axes);
        const Mesh m = surface(p);
        EXPECT_EQ(m.vertices.size(), 8u);
        EXPECT_EQ(m.triangles.size(), 12u);
        EXPECT_EQ(badEdges(m), 0);
        EXPECT_NEAR(signedVolume(m), boxVolume(p), 1e-4 * boxVolume(p));
        for (const glm::vec3& v : m.vertices) {
            const glm::vec3 u = unitCoordinates(p, v);
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::fabs(u[a]), 1.0f, 1e-5f);
        }
    }
}

TEST(Tessellation, CylinderIsAClosedOutwardPrismOnTheUnitCircle) {
    for (const Frame& f : frames()) {
        SCOPED_TRACE(f.name);
        const Primitive p = primitive(PrimitiveKind::Cylinder, f.axes);
        const Mesh m = surface(p);
        EXPECT_EQ(m.vertices.size(), std::size_t(2 * kRoundSides));
        EXPECT_EQ(m.triangles.size(), std::size_t(4 * kRoundSides - 4));
        EXPECT_EQ(badEdges(m), 0);
        const double prism = polygonArea() * boxVolume(p) / 4.0;
        EXPECT_NEAR(signedVolume(m), prism, 1e-4 * prism);
        EXPECT_NEAR(signedVolume(m), kPi / 4.0 * boxVolume(p), 0.03 * boxVolume(p));  // the analytic cylinder
        for (const glm::vec3& v : m.vertices) {
            const glm::vec3 u = unitCoordinates(p, v);
            EXPECT_NEAR(u.x * u.x + u.z * u.z, 1.0f, 1e-5f);
            EXPECT_NEAR(std::fabs(u.y), 1.0f, 1e-5f);  // the axis is the frame's y
        }
    }
}

TEST(Tessellation, FirstRoundVertexIsOnPlusXAndAnglesRunTowardsPlusZ) {
    const Primitive p = primitive(PrimitiveKind::Cylinder, glm::mat3(1.0f));
    const Mesh m = surface(p);
    const glm::vec3 u0 = unitCoordinates(p, m.vertices[0]), u1 = unitCoordinates(p, m.vertices[1]);
    EXPECT_NEAR(u0.x, 1.0f, 1e-6f);
    EXPECT_NEAR(u0.z, 0.0f, 1e-6f);
    const double a = 2.0 * kPi / kRoundSides;
    EXPECT_NEAR(u1.x, std::cos(a), 1e-6);
    EXPECT_NEAR(u1.z, std::sin(a), 1e-6);
}

TEST(Tessellation, ConeIsAClosedOutwardFrustumWithTheTaperedTopRadius) {
    for (const float taper : {0.0f, 0.25f, 0.5f, 1.0f}) {
        for (const Frame& f : frames()) {
            SCOPED_TRACE(std::string(f.name) + ", taper " + std::to_string(taper));
            const Primitive p = primitive(PrimitiveKind::Cone, f.axes, taper);
            const Mesh m = surface(p);
            if (taper == 0.0f) {  // a pyramid: one apex vertex, no top cap
                EXPECT_EQ(m.vertices.size(), std::size_t(kRoundSides + 1));
                EXPECT_EQ(m.triangles.size(), std::size_t(2 * kRoundSides - 2));
            } else {
                EXPECT_EQ(m.vertices.size(), std::size_t(2 * kRoundSides));
                EXPECT_EQ(m.triangles.size(), std::size_t(4 * kRoundSides - 4));
            }
            EXPECT_EQ(badEdges(m), 0);
            const double scale = (1.0 + taper + taper * taper) / 3.0;  // frustum of similar polygons
            const double frustum = polygonArea() * boxVolume(p) / 4.0 * scale;
            EXPECT_NEAR(signedVolume(m), frustum, 1e-4 * frustum);
            EXPECT_NEAR(signedVolume(m), kPi / 4.0 * boxVolume(p) * scale, 0.03 * boxVolume(p));
            for (const glm::vec3& v : m.vertices) {
                const glm::vec3 u = unitCoordinates(p, v);
                const float r = (1.0f + taper) / 2.0f + (taper - 1.0f) / 2.0f * u.y;  // primitive.hpp's r(y)
                EXPECT_NEAR(std::sqrt(u.x * u.x + u.z * u.z), r, 1e-5f);
                EXPECT_NEAR(std::fabs(u.y), 1.0f, 1e-5f);
            }
        }
    }
}

TEST(Tessellation, SphereIsAClosedOutwardUvSphereOnTheEllipsoid) {
    for (const Frame& f : frames()) {
        SCOPED_TRACE(f.name);
        const Primitive p = primitive(PrimitiveKind::Sphere, f.axes);
        const Mesh m = surface(p);
        EXPECT_EQ(m.vertices.size(), std::size_t(2 + kRoundSides * (kSphereStacks - 1)));
        EXPECT_EQ(m.triangles.size(), std::size_t(2 * kRoundSides * (kSphereStacks - 1)));
        EXPECT_EQ(badEdges(m), 0);
        const double ellipsoid = kPi / 6.0 * boxVolume(p);
        EXPECT_LT(signedVolume(m), ellipsoid);  // inscribed polyhedron
        EXPECT_GT(signedVolume(m), 0.9 * ellipsoid);
        for (const glm::vec3& v : m.vertices) EXPECT_NEAR(glm::length(unitCoordinates(p, v)), 1.0f, 1e-5f);
    }
}

/// Triangles with (nearly) no area: a degenerate top must not leave any behind.
int slivers(const Mesh& m) {
    int n = 0;
    for (const auto& t : m.triangles) {
        const glm::dvec3 a(m.vertices[t[0]]), b(m.vertices[t[1]]), c(m.vertices[t[2]]);
        n += glm::length(glm::cross(b - a, c - a)) < 1e-6;
    }
    return n;
}

Primitive roofPrimitive(const glm::mat3& axes, float tx, float tz) {
    Primitive p = primitive(PrimitiveKind::Roof, axes, tx);
    test::setKindParams(p, tx, tz);
    return p;
}

TEST(Tessellation, RoofIsAClosedOutwardBoxFrustumEvenWithARidgeOrAnApex) {
    const float fractions[][2] = {{1, 1}, {0.5f, 0.25f}, {0, 1}, {1, 0}, {0, 0.5f}, {0.75f, 0}, {0, 0}, {-3, NAN}, {0.5f, 0.5f}};
    for (const auto& t : fractions) {
        for (const Frame& f : frames()) {
            SCOPED_TRACE(std::string(f.name) + ", top " + std::to_string(t[0]) + " x " + std::to_string(t[1]));
            const Primitive p = roofPrimitive(f.axes, t[0], t[1]);
            const Mesh m = surface(p);
            const float tx = t[0] >= 0 ? std::min(t[0], 1.0f) : 0.0f, tz = t[1] >= 0 ? std::min(t[1], 1.0f) : 0.0f;
            const int zeros = (tx == 0) + (tz == 0);
            const std::size_t vertices[] = {8, 6, 5}, triangles[] = {12, 8, 6};
            EXPECT_EQ(m.vertices.size(), vertices[zeros]);
            EXPECT_EQ(m.triangles.size(), triangles[zeros]);
            EXPECT_EQ(badEdges(m), 0);
            EXPECT_EQ(slivers(m), 0);
            // integral over u.y of 4 rx rz: 8 (1 + (a + b) / 2 + a b / 3) per unit, a = tx - 1, b = tz - 1
            const double a = tx - 1.0, b = tz - 1.0, volume = (1 + (a + b) / 2 + a * b / 3) * boxVolume(p);
            EXPECT_NEAR(signedVolume(m), volume, 1e-4 * volume);
            for (const glm::vec3& v : m.vertices) {  // corners: the full square at the bottom, the top face on top
                const glm::vec3 u = unitCoordinates(p, v);
                ASSERT_NEAR(std::fabs(u.y), 1.0f, 1e-5f);
                EXPECT_NEAR(std::fabs(u.x), u.y < 0 ? 1.0f : tx, 1e-5f);
                EXPECT_NEAR(std::fabs(u.z), u.y < 0 ? 1.0f : tz, 1e-5f);
            }
        }
    }
}

TEST(Tessellation, ParaboloidIsAClosedOutwardPolyhedronInscribedInTheParaboloid) {
    for (const Frame& f : frames()) {
        SCOPED_TRACE(f.name);
        const Primitive p = primitive(PrimitiveKind::Paraboloid, f.axes);
        const Mesh m = surface(p);
        EXPECT_EQ(m.vertices.size(), std::size_t(kParaboloidRings * kRoundSides + 1));
        EXPECT_EQ(m.triangles.size(), std::size_t(2 * kParaboloidRings * kRoundSides - 2));
        EXPECT_EQ(badEdges(m), 0);
        EXPECT_EQ(slivers(m), 0);
        // frusta of similar polygons between the rings, a pyramid on top
        double polyhedron = 0;
        for (int i = 0; i < kParaboloidRings; ++i) {
            const double r = paraboloidRingRadius(i), h = (i + 1 < kParaboloidRings ? paraboloidRingHeight(i + 1) : 1.0) - paraboloidRingHeight(i);
            const double next = i + 1 < kParaboloidRings ? paraboloidRingRadius(i + 1) : 0.0;
            polyhedron += polygonArea() * h / 3 * (r * r + r * next + next * next);
        }
        polyhedron *= boxVolume(p) / 8;
        EXPECT_NEAR(signedVolume(m), polyhedron, 1e-4 * polyhedron);
        const double paraboloid = kPi / 8 * boxVolume(p);  // pi per unit of h.x h.y h.z
        EXPECT_LT(signedVolume(m), paraboloid);
        EXPECT_GT(signedVolume(m), 0.93 * paraboloid);
        for (const glm::vec3& v : m.vertices) {
            const glm::vec3 u = unitCoordinates(p, v);
            EXPECT_NEAR(u.x * u.x + u.z * u.z, (1 - u.y) / 2, 1e-5f);
            EXPECT_LE(std::fabs(u.y), 1 + 1e-5f);
        }
    }
}

/// The octahedron |x| + |y| + |z| <= 1 (volume 4/3), outward-facing.
MeshShape octahedron() {
    MeshShape s;
    s.path = "octahedron.obj";
    s.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) {
                const bool even = ((x == 0) == (y == 2)) == (z == 4);  // an even number of negative axes
                s.triangles.push_back(even ? std::array<std::uint32_t, 3>{x, y, z} : std::array<std::uint32_t, 3>{x, z, y});
            }
    return s;
}

TEST(Tessellation, MeshPrimitivePlacesTheGrammarMeshInItsFrame) {
    const std::vector<MeshShape> meshes = {MeshShape{}, octahedron()};
    ASSERT_GT(signedVolume(Mesh{meshes[1].vertices, meshes[1].triangles, {}, {}, {}, {}}), 0.0) << "test mesh wound inwards";
    for (const Frame& f : frames()) {
        SCOPED_TRACE(f.name);
        Primitive p = primitive(PrimitiveKind::Mesh, f.axes);
        setParams<MeshKind>(p, {1});
        const Mesh m = surface(p, &meshes);
        EXPECT_EQ(m.vertices.size(), 6u);
        EXPECT_EQ(m.triangles.size(), 8u);
        EXPECT_EQ(badEdges(m), 0);
        const double volume = 4.0 / 3.0 * boxVolume(p) / 8.0;
        EXPECT_NEAR(signedVolume(m), volume, 1e-4 * volume);
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
            for (int a = 0; a < 3; ++a)
                EXPECT_NEAR(unitCoordinates(p, m.vertices[i])[a], meshes[1].vertices[i][a], 1e-5f);
    }
}

TEST(Tessellation, MeshPrimitiveWithoutItsMeshThrows) {
    Primitive p = primitive(PrimitiveKind::Mesh, glm::mat3(1.0f));
    setParams<MeshKind>(p, {2});
    const std::vector<MeshShape> meshes(2);
    EXPECT_THROW(surface(p, nullptr), std::out_of_range);
    EXPECT_THROW(surface(p, &meshes), std::out_of_range);
}

TEST(Tessellation, MeshOfAModelAppendsEveryPrimitiveWithItsOwnIndices) {
    const std::vector<MeshShape> meshes = {octahedron()};
    Geometry g;
    g.meshes = &meshes;
    double expected = 0;
    std::size_t vertices = 0, triangles = 0;
    for (const Frame& f : frames())
        for (PrimitiveKind k : {PrimitiveKind::Box, PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Sphere,
                                PrimitiveKind::Mesh, PrimitiveKind::Roof, PrimitiveKind::Paraboloid}) {
            g.primitives.push_back(primitive(k, f.axes, 0.5f));
            const Mesh alone = surface(g.primitives.back(), &meshes);
            expected += signedVolume(alone);
            vertices += alone.vertices.size();
            triangles += alone.triangles.size();
        }
    const Mesh m = meshOf(g);
    EXPECT_EQ(m.vertices.size(), vertices);
    EXPECT_EQ(m.triangles.size(), triangles);
    EXPECT_EQ(badEdges(m), 0);
    EXPECT_NEAR(signedVolume(m), expected, 1e-4 * expected);
    EXPECT_GT(expected, 0.0);
}

}  // namespace
}  // namespace shapevo
