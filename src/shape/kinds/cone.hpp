// The Cone kind: `cone` (a pointed cone, taper 0) or `cone top EXPR` (a frustum, taper = EXPR
// clamped to [0, 1] when derived; NaN -> 0) in a grammar. Solid: a frustum u.x^2 + u.z^2 <=
// r(u.y)^2, |u.y| <= 1 with r(y) = (1 + taper)/2 + (taper - 1)/2 * y (radius 1 at the bottom,
// `taper` at the top): ConeSolid, its voxel-centre inside test and the chord of a voxel row
// (shape/chord_rows.hpp explains why the test is written per row and why that makes the row
// interval exact). Silhouette: the kRoundSides-gon frustum, or the ring and the apex for taper 0.
// Surface: the same frustum (kRoundSides + 1 vertices for a pointed cone).
//
// Along a row, with dx an offset along it: (u.x, u.z) = A dx + B and r = rho dx + sigma, so the
// lateral surface is one quadratic f(dx) = |A dx + B|^2 - (rho dx + sigma)^2 <= 0 (set up around
// the row's point closest to the axis). Its solutions lie on both nappes of the double cone; the
// frustum's nappe is the one with r >= 0, and the end caps' slab cuts it.
#pragma once
#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// dx with k dx^2 + 2 b dx + c <= 0 on the side where rho dx + sigma grows (for k < 0 the
/// solutions are two rays, one per nappe), intersected with rho dx + sigma >= 0.
inline Chord nappeChord(double k, double b, double c, double rho, double sigma) {
    Chord q;
    if (std::isnan(k) || std::isnan(b) || std::isnan(c)) return Chord::none();
    if (k == 0.0) {  // the row is parallel to a generator: one ray (or everything, or nothing)
        if (b == 0.0) {
            q = c <= 0.0 ? Chord::all() : Chord::none();
        } else {
            const double r = -c / (2.0 * b);
            q = b > 0.0 ? Chord{-INFINITY, r} : Chord{r, INFINITY};
        }
    } else {
        const double disc = b * b - k * c;
        if (std::isnan(disc)) return Chord::none();
        if (k > 0.0) {  // an interval, on one nappe
            if (disc < 0.0) return Chord::none();
            const double s = -(b + std::copysign(std::sqrt(disc), b));  // no cancellation
            if (s == 0.0) {
                q = {0.0, 0.0};
            } else {
                const double r1 = s / k, r2 = c / s;
                q = {std::min(r1, r2), std::max(r1, r2)};
            }
        } else if (!(disc > 0.0)) {  // k < 0 and no real roots: f <= 0 on the whole line
            q = Chord::all();
        } else {  // k < 0 (so rho != 0): keep the ray on the side where r grows
            const double s = -(b + std::copysign(std::sqrt(disc), b));
            const double r1 = s / k, r2 = c / s;
            q = rho > 0.0 ? Chord{std::max(r1, r2), INFINITY} : Chord{-INFINITY, std::min(r1, r2)};
        }
    }
    Chord positive;  // r >= 0
    if (rho > 0.0) positive = {-sigma / rho, INFINITY};
    else if (rho < 0.0) positive = {-INFINITY, -sigma / rho};
    else positive = sigma >= 0.0 ? Chord::all() : Chord::none();
    return q & positive;
}

/// The cone's own parameters (ConeKind::Params, kept in Primitive::params): the top radius / the
/// bottom radius, in [0, 1] when derived.
struct ConeParams {
    float taper = 1.0f;
};

struct ConeSolid {
    RoundFrame f;
    double radialSlope[2];  ///< du_x / dx and du_z / dx along every row
    double axialSlope;      ///< du_y / dx
    double r0, r1;          ///< r(y) = r0 + r1 * y
    double radialSq;        ///< |A|^2: squared radial slope
    double rho, kk;         ///< dr / dx along a row; the quadratic's leading coefficient |A|^2 - rho^2

    static ConeSolid from(const Primitive& p) {
        ConeSolid s{RoundFrame::from(p), {}, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        const float t = p.params.as<ConeParams>().taper;
        const double taper = t >= 0.0f ? std::min(double(t), 1.0) : 0.0;  // NaN -> 0, as derive
        s.r0 = (1.0 + taper) * 0.5;
        s.r1 = (taper - 1.0) * 0.5;
        s.radialSlope[0] = s.f.slope(0);
        s.radialSlope[1] = s.f.slope(2);
        s.axialSlope = s.f.slope(1);
        s.rho = s.r1 * s.axialSlope;
        s.radialSq = s.radialSlope[0] * s.radialSlope[0] + s.radialSlope[1] * s.radialSlope[1];
        s.kk = s.radialSq - s.rho * s.rho;
        return s;
    }
    bool valid() const { return f.valid(); }
    double cx() const { return f.cx(); }
    /// World-space half extent of the bounding box along grid axis j (that of the cylinder
    /// around the frustum: the radius is at most 1).
    double reach(int j) const { return std::fabs(f.box.a[1][j]) * f.box.h[1] + f.ellipseReach(0, 2, j); }
    /// Offsets x - c.x inside the frustum on row (y, z).
    Chord chord(double y, double z) const {
        const double v = f.atCentre(1, y, z);
        const Chord caps = slabChord(axialSlope, v);
        if (caps.empty()) return caps;
        // The quadratic is set up around the point of the row closest to the axis (offset mid).
        const auto [mid, ux, uz] = nearestToAxis(radialSlope, radialSq, f.atCentre(0, y, z), f.atCentre(2, y, z));
        const double sigma = r0 + r1 * (axialSlope * mid + v);
        const double b = radialSlope[0] * ux + radialSlope[1] * uz - rho * sigma;
        const double c = ux * ux + uz * uz - sigma * sigma;
        const Chord lateral = nappeChord(kk, b, c, rho, sigma);
        return caps & Chord{lateral.lo + mid, lateral.hi + mid};
    }
    /// The voxel-centre test: is point (x, y, z) inside the closed frustum? (Never, if not valid().)
    bool contains(double x, double y, double z) const { return valid() && chord(y, z).contains(x - cx()); }
};

struct ConeKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Cone;
    static constexpr std::string_view keyword = "cone";
    using Params = ConeParams;
    /// Grammar: optional `top EXPR`, the top radius ratio (expression 0; a constant 0 without it).
    template <class Args>
    static void parseArguments(Args& a) {
        a.optionalExpression("top", 0.0f);
    }
    template <class Args>
    static void emit(Primitive& p, const Args& a) {
        const float top = a.expression(0);
        setParams<ConeKind>(p, {top >= 0.0f ? std::min(top, 1.0f) : 0.0f});  // NaN -> 0 as well
    }
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        voxelizeChords(ConeSolid::from(p), rows, counts);
    }
    /// Its silhouette state, one per outline builder: the builder's prism, whose top ring (vertices
    /// kRoundSides .. 2 kRoundSides - 1) `outline` rescales by the taper.
    struct OutlineScratch {
        UnitShape frustum;
        template <class Builder>
        explicit OutlineScratch(const Builder& b) : frustum(b.prismShape()) {}
    };
    /// The round two-ring fast path with the top ring scaled by the taper; else the pyramid (taper
    /// not > 0) or the prism with its top ring scaled, as one convex piece.
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive& p, Outline& out) {
        const float taper = paramsOf<ConeKind>(p).taper;
        if (b.addRingsFast(map, nullptr, std::clamp(double(taper), 0.0, 1.0), out)) return;  // (NaN: 0)
        if (!(taper > 0.0f)) {
            b.addConvex(map, b.pyramidShape(), out);
        } else {
            const auto& prism = b.prismShape();
            UnitShape& cone = b.template scratch<ConeKind>().frustum;
            const std::size_t n = prism.ringSize;
            for (std::size_t k = 0; k < n; ++k) {
                const glm::dvec3& v = prism.vertices[n + k];
                const double t = std::min(double(taper), 1.0);
                cone.vertices[n + k] = {v.x * t, v.y, v.z * t};
            }
            b.addConvex(map, cone, out);
        }
    }
    static void surface(SurfaceBuilder& s, const Primitive& p, const std::vector<MeshShape>*) {
        frustumSurface(s, paramsOf<ConeKind>(p).taper);
    }
    /// Textures: its sides are mapped cylindrically at this mean radius (geometry/texture_uv.hpp).
    static float textureRadius(const Primitive& p) { return meanCrossRadius(p) * 0.5f * (1.0f + paramsOf<ConeKind>(p).taper); }
};

}  // namespace shapevo
