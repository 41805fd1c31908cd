// SurfaceBuilder: what the kinds' tessellation code (shape/kinds/*.hpp, `surface`) writes into.
// A kind builds its surface in the frame's unit coordinates u (shape/primitive.hpp); the builder
// places each vertex with world = centre + axes * (half * u) and reverses triangles of mirrored
// frames (det(axes) < 0), so that a closed piece given outward counter-clockwise in u still
// faces outwards. Also the ring and frustum pieces the round kinds share.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// A round kind's radius before its profile: the mean of its half extents across its axis,
/// (|half.x| + |half.z|) / 2, in world units (the round kinds' textureRadius starts from it).
inline float meanCrossRadius(const Primitive& p) { return 0.5f * (std::fabs(p.half.x) + std::fabs(p.half.z)); }

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
inline glm::vec3 ringPoint(int k, float radius, float y) {
    const double a = 2.0 * std::numbers::pi * double(k) / double(kRoundSides);
    return {float(radius * std::cos(a)), y, float(radius * std::sin(a))};
}

/// A kRoundSides-gon frustum, bottom ring radius 1 at u.y = -1, top ring `topRadius` at u.y = 1
/// (a pyramid with one apex vertex if topRadius is not > 0). Ring angles run from +x towards +z,
/// i.e. clockwise seen from +y: the side quad (bottom k, top k, top k+1, bottom k+1) faces
/// outwards, the bottom cap is a fan in ring order and the top cap a fan in reverse order.
inline void frustumSurface(SurfaceBuilder& s, float topRadius) {
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

}  // namespace shapevo
