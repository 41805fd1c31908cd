// The Paraboloid kind: `paraboloid` in a grammar (no arguments; CastleMaker's
// insert_parabolic_cone). Solid (shape/primitive.hpp): u.x^2 + u.z^2 <= (1 - u.y)/2, |u.y| <= 1,
// the solid of revolution of a parabola filling the scope: radius 1 at the bottom (u.y = -1),
// apex at the top, elliptic when half.x != half.z. ParaboloidSolid is the exact voxel-centre test,
// written per row like the other round kinds (shape/chord_rows.hpp explains why that makes the
// row interval exact): along a row the paraboloid is one quadratic inequality with a leading
// coefficient >= 0, so its chord is one interval, cut by the caps' slab.
// Silhouette and surface: the inscribed convex polyhedron of kParaboloidRings kRoundSides-gon
// rings (vertices on the surface, at the ring angles of the other round kinds) and the apex,
// drawn at full detail (no level of detail, no fast path).
//
// Along a row, with d the offset from the row's point closest to the axis, (u.x, u.z) = A d + B
// (A . B = 0) and u.y = s d + v, the lateral surface is f(d) = |A|^2 d^2 + 2 b d + c <= 0 with
// b = s / 4 and c = |B|^2 - (1 - v) / 2; the roots are taken in the form that does not cancel.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// The polyhedron standing in for the paraboloid in silhouettes and exported meshes: rings i = 0
/// .. kParaboloidRings - 1 of radius r_i = 1 - i / kParaboloidRings at height u.y = 1 - 2 r_i^2
/// (radii 1, 3/4, 1/2, 1/4 at u.y = -1, -1/8, 1/2, 7/8), then the apex (0, 1, 0). Equal radius
/// steps keep every chord of the profile within 1/32 (in u.y) of the parabola, about as close as
/// the 16-gon is to the circle.
inline constexpr int kParaboloidRings = 4;
inline constexpr double paraboloidRingRadius(int i) { return 1.0 - double(i) / double(kParaboloidRings); }
inline constexpr double paraboloidRingHeight(int i) {
    const double r = paraboloidRingRadius(i);
    return 1.0 - 2.0 * r * r;
}

/// Offsets d with k d^2 + 2 b d + c <= 0, for k >= 0 (a convex quadratic: one interval, a ray
/// when k == 0, or nothing). NaN: nothing.
inline Chord convexQuadraticChord(double k, double b, double c) {
    if (!(k > 0.0)) {  // the row runs along the axis: 2 b d + c <= 0
        if (!(k == 0.0)) return Chord::none();
        if (b == 0.0) return c <= 0.0 ? Chord::all() : Chord::none();
        const double r = -c / (2.0 * b);
        return b > 0.0 ? Chord{-INFINITY, r} : Chord{r, INFINITY};
    }
    const double disc = b * b - k * c;
    if (!(disc >= 0.0)) return Chord::none();
    const double s = -(b + std::copysign(std::sqrt(disc), b));  // |s| >= |b|: no cancellation
    if (s == 0.0) return {0.0, 0.0};                            // b = c = 0: the single root 0
    const double r1 = s / k, r2 = c / s;
    return {std::min(r1, r2), std::max(r1, r2)};
}

struct ParaboloidSolid {
    RoundFrame f;
    double radialSlope[2];  ///< du_x / dx and du_z / dx along every row
    double axialSlope;      ///< du_y / dx
    double radialSq;        ///< |A|^2, the quadratic's leading coefficient

    static ParaboloidSolid from(const Primitive& p) {
        ParaboloidSolid s{RoundFrame::from(p), {}, 0.0, 0.0};
        s.radialSlope[0] = s.f.slope(0);
        s.radialSlope[1] = s.f.slope(2);
        s.axialSlope = s.f.slope(1);
        s.radialSq = s.radialSlope[0] * s.radialSlope[0] + s.radialSlope[1] * s.radialSlope[1];
        return s;
    }
    bool valid() const { return f.valid(); }
    double cx() const { return f.cx(); }
    /// World-space half extent of the bounding box along grid axis j (that of the cylinder
    /// around the paraboloid: the radius is at most 1).
    double reach(int j) const { return std::fabs(f.box.a[1][j]) * f.box.h[1] + f.ellipseReach(0, 2, j); }
    /// Offsets x - c.x inside the paraboloid on row (y, z).
    Chord chord(double y, double z) const {
        const double v = f.atCentre(1, y, z);
        const Chord caps = slabChord(axialSlope, v);
        if (caps.empty()) return caps;
        // Around the point of the row closest to the axis (offset mid), where u.x, u.z are small
        // for every row that meets the solid.
        const auto [mid, ux, uz] = nearestToAxis(radialSlope, radialSq, f.atCentre(0, y, z), f.atCentre(2, y, z));
        const double uy = axialSlope * mid + v;
        const double b = radialSlope[0] * ux + radialSlope[1] * uz + 0.25 * axialSlope;
        const double c = ux * ux + uz * uz - 0.5 * (1.0 - uy);
        const Chord lateral = convexQuadraticChord(radialSq, b, c);
        return caps & Chord{lateral.lo + mid, lateral.hi + mid};
    }
    /// The voxel-centre test: is point (x, y, z) inside the closed paraboloid? (Never, if not valid().)
    bool contains(double x, double y, double z) const { return valid() && chord(y, z).contains(x - cx()); }
};

struct ParaboloidKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Paraboloid;
    static constexpr std::string_view keyword = "paraboloid";
    /// Grammar: no arguments; a word that does not start the next statement is a located error.
    template <class Args>
    static void parseArguments(Args& a) {
        if (!a.atStatementEnd()) a.expected("the next statement after 'paraboloid' (it takes no arguments)");
    }
    template <class Args>
    static void emit(Primitive&, const Args&) {}
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        voxelizeChords(ParaboloidSolid::from(p), rows, counts);
    }
    /// Its silhouette state, one per outline builder: the polyhedron as a unit shape
    /// (kParaboloidRings round rings, then the apex joined to the last ring).
    struct OutlineScratch {
        UnitShape polyhedron;
        template <class Builder>
        explicit OutlineScratch(const Builder&) : polyhedron(Builder::roundShape(rings(), {{{0.0, 1.0, 0.0}, kParaboloidRings - 1}})) {}
        /// (radius, u.y) of each ring.
        static std::vector<glm::dvec2> rings() {
            std::vector<glm::dvec2> r;
            for (int i = 0; i < kParaboloidRings; ++i) r.push_back({paraboloidRingRadius(i), paraboloidRingHeight(i)});
            return r;
        }
    };
    /// The polyhedron's kParaboloidRings * kRoundSides + 1 vertices as one convex piece.
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive&, Outline& out) {
        b.addConvex(map, b.template scratch<ParaboloidKind>().polyhedron, out);
    }
    /// Textures: its sides are mapped cylindrically at this mean radius, its radius averaged over
    /// its height (geometry/texture_uv.hpp).
    static float textureRadius(const Primitive& p) { return meanCrossRadius(p) * (2.0f / 3.0f); }
    /// Surface: ring i's vertices at i * kRoundSides + k, the apex last; the bottom cap a fan in
    /// ring order, the bands quads (ring i k, ring i+1 k, ring i+1 k+1, ring i k+1), the top a fan
    /// of triangles to the apex: kParaboloidRings * kRoundSides + 1 vertices and
    /// 2 * kParaboloidRings * kRoundSides - 2 triangles.
    static void surface(SurfaceBuilder& s, const Primitive&, const std::vector<MeshShape>*) {
        constexpr std::uint32_t n = kRoundSides;
        for (int i = 0; i < kParaboloidRings; ++i)
            for (int k = 0; k < kRoundSides; ++k)
                s.vertex(ringPoint(k, float(paraboloidRingRadius(i)), float(paraboloidRingHeight(i))));
        const std::uint32_t apex = s.vertex({0.0f, 1.0f, 0.0f});
        const auto ring = [](int i, std::uint32_t k) { return std::uint32_t(i) * n + k % n; };
        for (std::uint32_t k = 1; k + 1 < n; ++k) s.triangle(0, k, k + 1);
        for (std::uint32_t k = 0; k < n; ++k) {
            for (int i = 0; i + 1 < kParaboloidRings; ++i) s.quad(ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1));
            s.triangle(ring(kParaboloidRings - 1, k), apex, ring(kParaboloidRings - 1, k + 1));
        }
    }
};

}  // namespace shapevo
