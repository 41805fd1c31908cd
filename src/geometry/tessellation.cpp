// Tessellation of each primitive kind in unit coordinates, then placement in the primitive's frame.
#include "geometry/tessellation.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/glm.hpp>

namespace shapevo {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

/// Builds one primitive's surface: vertices in unit coordinates are placed in the frame as they
/// are added; triangles are given counter-clockwise seen from outside in the unit frame (a
/// right-handed frame) and reversed when the frame is mirrored.
class SurfaceBuilder {
public:
    SurfaceBuilder(const Primitive& p, Mesh& out)
        : p_(p), out_(out), base_(std::uint32_t(out.vertices.size())), mirrored_(glm::determinant(p.axes) < 0.0f) {}

    /// Adds a vertex at unit coordinates u; returns its index within this primitive.
    std::uint32_t vertex(const glm::vec3& u) {
        out_.vertices.push_back(p_.centre + p_.axes * (p_.half * u));
        return std::uint32_t(out_.vertices.size()) - base_ - 1;
    }
    /// Adds a triangle of this primitive's vertex indices (outward counter-clockwise in u).
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (mirrored_) std::swap(b, c);
        out_.triangles.push_back({base_ + a, base_ + b, base_ + c});
    }
    /// Two triangles of the quad a, b, c, d (outward counter-clockwise in u).
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

private:
    const Primitive& p_;
    Mesh& out_;
    std::uint32_t base_;
    bool mirrored_;
};

/// Point k of a unit-radius ring at height y: angle 2*pi*k/kRoundSides from +x towards +z.
glm::vec3 ringPoint(int k, float radius, float y) {
    const double a = 2.0 * std::numbers::pi * double(k) / double(kRoundSides);
    return {float(radius * std::cos(a)), y, float(radius * std::sin(a))};
}

void addBox(SurfaceBuilder& s) {
    // Corners indexed by bits (x, y, z) = (i & 1, i >> 1 & 1, i >> 2 & 1); quads -x, +x, -y, +y, -z, +z.
    constexpr std::uint32_t kQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (int i = 0; i < 8; ++i) s.vertex({(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f});
    for (const auto& q : kQuads) s.quad(q[0], q[1], q[2], q[3]);
}

/// Ring angles run from +x towards +z, i.e. clockwise seen from +y: the side quad
/// (bottom k, top k, top k+1, bottom k+1) faces outwards, the bottom cap is a fan in ring order
/// and the top cap a fan in reverse order.
void addFrustum(SurfaceBuilder& s, float topRadius) {
    constexpr std::uint32_t n = kRoundSides;
    for (int k = 0; k < kRoundSides; ++k) s.vertex(ringPoint(k, 1.0f, -1.0f));  // bottom ring: 0 .. n-1
    if (!(topRadius > 0.0f)) {                                                    // a pointed cone (NaN too)
        const std::uint32_t apex = s.vertex({0.0f, 1.0f, 0.0f});
        for (std::uint32_t k = 0; k < n; ++k) s.triangle(k, apex, (k + 1) % n);
    } else {
        for (int k = 0; k < kRoundSides; ++k) s.vertex(ringPoint(k, topRadius, 1.0f));  // top ring: n .. 2n-1
        for (std::uint32_t k = 0; k < n; ++k) s.quad(k, n + k, n + (k + 1) % n, (k + 1) % n);
        for (std::uint32_t k = 1; k + 1 < n; ++k) s.triangle(n, n + k + 1, n + k);
    }
    for (std::uint32_t k = 1; k + 1 < n; ++k) s.triangle(0, k, k + 1);
}

void addSphere(SurfaceBuilder& s) {
    constexpr std::uint32_t n = kRoundSides;
    const std::uint32_t south = s.vertex({0.0f, -1.0f, 0.0f});
    for (int i = 1; i < kSphereStacks; ++i) {  // ring i - 1 starts at vertex 1 + (i - 1) * n
        const double lat = std::numbers::pi * (double(i) / kSphereStacks - 0.5);
        for (int k = 0; k < kRoundSides; ++k) s.vertex(ringPoint(k, float(std::cos(lat)), float(std::sin(lat))));
    }
    const std::uint32_t north = s.vertex({0.0f, 1.0f, 0.0f});
    const auto ring = [](int r, std::uint32_t k) { return 1 + std::uint32_t(r) * n + k % n; };
    for (std::uint32_t k = 0; k < n; ++k) {
        s.triangle(south, ring(0, k), ring(0, k + 1));
        for (int r = 0; r + 1 < kSphereStacks - 1; ++r) s.quad(ring(r, k), ring(r + 1, k), ring(r + 1, k + 1), ring(r, k + 1));
        s.triangle(ring(kSphereStacks - 2, k), north, ring(kSphereStacks - 2, k + 1));
    }
}

void addMesh(SurfaceBuilder& s, const Primitive& p, const std::vector<MeshShape>* meshes) {
    if (!meshes || p.mesh >= meshes->size())
        throw std::out_of_range("mesh primitive refers to mesh " + std::to_string(p.mesh) + " but the model has " +
                                std::to_string(meshes ? meshes->size() : 0));
    const MeshShape& m = (*meshes)[p.mesh];
    for (const glm::vec3& v : m.vertices) s.vertex(v);
    for (const auto& t : m.triangles) s.triangle(t[0], t[1], t[2]);
}

}  // namespace

void appendSurface(const Primitive& p, const std::vector<MeshShape>* meshes, Mesh& out) {
    SurfaceBuilder s(p, out);
    switch (p.kind) {
    case PrimitiveKind::Box: addBox(s); break;
    case PrimitiveKind::Cylinder: addFrustum(s, 1.0f); break;
    case PrimitiveKind::Cone: addFrustum(s, p.taper); break;
    case PrimitiveKind::Sphere: addSphere(s); break;
    case PrimitiveKind::Mesh: addMesh(s, p, meshes); break;
    }
}

Mesh tessellate(const Geometry& geometry) {
    Mesh m;
    for (const Primitive& p : geometry.primitives) appendSurface(p, geometry.meshes, m);
    return m;
}

}  // namespace shapevo
