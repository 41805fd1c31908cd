// The Roof kind: `roof` in a grammar, a convex "box frustum" filling the scope (CastleMaker's
// insert_volume). Solid (shape/primitive.hpp): |u.x| <= rx(u.y), |u.z| <= rz(u.y), |u.y| <= 1 with
// r(y) = (1 + t)/2 + (t - 1)/2 * y, t = taper for x and taperZ for z: the full square at the
// bottom, the rectangle |u.x| <= taper, |u.z| <= taperZ on top, the convex hull in between.
// Grammar forms (parseArguments; emit turns them into the two fractions, clamped to [0, 1],
// NaN -> 0):
//   roof top (EX, EZ)   the top face's fractions along x and z (two scalar expressions)
//   roof gable          a ridge along the scope's longer horizontal axis (|half.x| >= |half.z|:
//                       along x, ties included): fraction 1 along the longer axis, 0 along the other
//   roof hip            equal slopes on all four sides: 0 along the shorter axis, 1 - short/long
//                       (half extents) along the longer one; a square scope gives a pyramid
//   roof pyramid        both 0: an apex
//   roof                the same as `roof gable`
// RoofSolid is the exact voxel-centre test, written per row like the round kinds (shape/
// chord_rows.hpp): along a row every face is linear in the offset, so the chord is the cap slab
// cut by four half-lines. Silhouette: the 8 corners as one convex piece (a square frustum, equal
// fractions, takes the builder's two-ring fast path). Surface: the same convex polyhedron; a
// ridge top has 6 vertices and 8 triangles, an apex 5 and 6 (no zero-area triangles).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// A roof's top-face fraction as every part of the kind reads it: clamped to [0, 1], NaN -> 0.
inline float roofFraction(float t) { return t >= 0.0f ? std::min(t, 1.0f) : 0.0f; }

/// Offsets dx with a * dx <= b (a half-line; all or nothing when a == 0; nothing for NaN).
inline Chord halfLineChord(double a, double b) {
    if (a > 0.0) return {-INFINITY, b / a};
    if (a < 0.0) return {b / a, INFINITY};
    return a == 0.0 && b >= 0.0 ? Chord::all() : Chord::none();
}

/// The roof's own parameters (RoofKind::Params, kept in Primitive::params): the top face / the
/// bottom face along x (taper) and along z (taperZ), in [0, 1] when derived.
struct RoofParams {
    float taper = 1.0f;
    float taperZ = 1.0f;
};

struct RoofSolid {
    RoundFrame f;
    double slope[3];     ///< du_k / dx along every row
    double r0[2], r1[2];  ///< half widths along x ([0]) and z ([1]): r(u.y) = r0 + r1 * u.y

    static RoofSolid from(const Primitive& p) {
        RoofSolid s{RoundFrame::from(p), {}, {}, {}};
        for (int k = 0; k < 3; ++k) s.slope[k] = s.f.slope(k);
        const auto params = p.params.as<RoofParams>();
        const double t[2] = {roofFraction(params.taper), roofFraction(params.taperZ)};
        for (int i = 0; i < 2; ++i) {
            s.r0[i] = (1.0 + t[i]) * 0.5;
            s.r1[i] = (t[i] - 1.0) * 0.5;
        }
        return s;
    }
    /// Finite with three positive half extents (a flat roof has no volume: it covers nothing).
    bool valid() const { return f.valid(); }
    double cx() const { return f.cx(); }
    /// World-space half extent of the bounding box along grid axis j (that of the whole box).
    double reach(int j) const { return f.box.reach(j); }
    /// Offsets x - c.x inside the roof on row (y, z).
    Chord chord(double y, double z) const {
        const double v = f.atCentre(1, y, z);
        Chord c = slabChord(slope[1], v);
        if (c.empty()) return c;
        // Face pair i: -r <= u_k <= r with u_k = slope_k dx + at and r = rho dx + sigma along the row.
        for (int i = 0; i < 2; ++i) {
            const int k = 2 * i;
            const double at = f.atCentre(k, y, z);
            const double rho = r1[i] * slope[1], sigma = r0[i] + r1[i] * v;
            c = c & halfLineChord(slope[k] - rho, sigma - at) & halfLineChord(-slope[k] - rho, sigma + at);
        }
        return c;
    }
    /// The voxel-centre test: is point (x, y, z) inside the closed roof? (Never, if not valid().)
    bool contains(double x, double y, double z) const { return valid() && chord(y, z).contains(x - cx()); }
};

struct RoofKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Roof;
    static constexpr std::string_view keyword = "roof";
    /// The grammar form, kept in the statement's slot.
    enum Form : std::uint16_t { Gable = 0, Hip = 1, Pyramid = 2, Top = 3 };
    using Params = RoofParams;

    /// Grammar: `top (EX, EZ)` (expressions 0 and 1), `gable`, `hip`, `pyramid` or nothing (gable).
    /// A word that is neither a form nor the start of the next statement is a located error.
    template <class Args>
    static void parseArguments(Args& a) {
        if (a.word("top")) {
            a.expect('(', "after 'roof top' (the form is roof top (X, Z))");
            a.expression(0);
            a.expect(',', "between the two fractions of 'roof top (X, Z)'");
            a.expression(1);
            a.expect(')', "after the two fractions of 'roof top (X, Z)'");
            a.tag(Top);
        } else if (a.word("gable")) {
            a.tag(Gable);
        } else if (a.word("hip")) {
            a.tag(Hip);
        } else if (a.word("pyramid")) {
            a.tag(Pyramid);
        } else if (a.atStatementEnd()) {
            a.tag(Gable);
        } else {
            a.expected("a roof form after 'roof' (top (X, Z), gable, hip or pyramid) or the next statement");
        }
    }
    /// Derivation: the two top-face fractions from the form (p.half is already the scope's).
    template <class Args>
    static void emit(Primitive& p, const Args& a) {
        float x = 0.0f, z = 0.0f;
        const float hx = p.half.x, hz = p.half.z;
        switch (a.slot()) {
        case Top:
            x = a.expression(0);
            z = a.expression(1);
            break;
        case Gable:  // the ridge along the longer axis, along x on a tie
            if (hx >= hz) x = 1.0f;
            else z = 1.0f;
            break;
        case Hip:  // the ridge shortened by the shorter half extent at both ends (0 / 0: NaN -> 0)
            if (hx >= hz) x = 1.0f - hz / hx;
            else z = 1.0f - hx / hz;
            break;
        default: break;  // Pyramid
        }
        setParams<RoofKind>(p, {roofFraction(x), roofFraction(z)});
    }
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        voxelizeChords(RoofSolid::from(p), rows, counts);
    }

    /// Its silhouette state, one per outline builder: the builder's box, whose top ring (vertices
    /// 4 .. 7) `outline` rescales by the fractions.
    struct OutlineScratch {
        UnitShape roof;
        template <class Builder>
        explicit OutlineScratch(const Builder& b) : roof(b.boxShape()) {}
    };
    /// Equal fractions: the square two-ring fast path (a square frustum, or a pyramid for 0); else
    /// (or when cut) the 8 corners, top ring scaled, as one convex piece.
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive& p, Outline& out) {
        const auto params = paramsOf<RoofKind>(p);
        const double tx = roofFraction(params.taper), tz = roofFraction(params.taperZ);
        if (tx == tz && b.addRingsFast(map, &b.squareRing(), tx, out)) return;
        const auto& box = b.boxShape();
        UnitShape& roof = b.template scratch<RoofKind>().roof;
        for (std::size_t k = 4; k < 8; ++k) {
            const glm::dvec3& v = box.vertices[k];  // the top ring: k = 4 .. 7
            roof.vertices[k] = {v.x * tx, v.y, v.z * tz};
        }
        b.addConvex(map, roof, out);
    }

    /// Surface: the bottom ring b_k = (x, z) in {(-1,-1), (1,-1), (1,1), (-1,1)} (angles from +x
    /// towards +z, as frustumSurface's), the top corners scaled by the fractions, with corners
    /// that coincide (a fraction 0) merged; side k is the quad b_k, t_k, t_k+1, b_k+1, or a
    /// triangle when t_k = t_k+1; the top cap only when it has 4 corners.
    static void surface(SurfaceBuilder& s, const Primitive& p, const std::vector<MeshShape>*) {
        constexpr float kRing[4][2] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
        const auto params = paramsOf<RoofKind>(p);
        const float tx = roofFraction(params.taper), tz = roofFraction(params.taperZ);
        for (const auto& c : kRing) s.vertex({c[0], -1.0f, c[1]});  // bottom: 0 .. 3
        std::uint32_t top[4];
        glm::vec3 at[4];
        std::uint32_t next = 4, distinct = 0;
        for (int k = 0; k < 4; ++k) {
            at[k] = {kRing[k][0] * tx, 1.0f, kRing[k][1] * tz};  // 0 * -1 is -0, which == 0
            top[k] = next;
            for (int j = 0; j < k; ++j)
                if (at[j] == at[k]) top[k] = top[j];
            if (top[k] == next) s.vertex(at[k]), ++next, ++distinct;
        }
        for (std::uint32_t k = 0; k < 4; ++k) {
            const std::uint32_t n = (k + 1) % 4;
            if (top[k] == top[n]) s.triangle(k, top[k], n);
            else s.quad(k, top[k], top[n], n);
        }
        s.triangle(0, 1, 2);
        s.triangle(0, 2, 3);
        if (distinct == 4) {
            s.triangle(top[0], top[2], top[1]);
            s.triangle(top[0], top[3], top[2]);
        }
    }
};

}  // namespace shapevo
