// The Sphere kind: `sphere` in a grammar (no arguments). Solid |u| <= 1, an ellipsoid filling its
// frame's box: SphereSolid, its voxel-centre inside test and the chord of a voxel row
// (shape/chord_rows.hpp explains why the test is written per row and why that makes the row
// interval exact). Silhouette: kSphereSides points on the contact curve (fewer when it projects
// small), or the UV polyhedron when cut or flat (score/image/silhouette_outline.hpp). Surface: a UV
// sphere of kRoundSides slices and kSphereStacks stacks (poles on the y axis).
#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// The same for the sphere's contact curve (kSphereSides points; levels 1, 2: 16 and 8 points
/// within 0.0192 r and 0.0761 r of the circle).
inline constexpr double kSphereLevelRadius[kRoundLevels] = {INFINITY, 0.25 / 0.0192, 0.25 / 0.0761};
inline constexpr int kSphereSides = 2 * kRoundSides;
/// Latitude bands of the tessellated UV sphere (kRoundSides meridians); vertex rings at latitudes
/// -90 + 180 * i / kSphereStacks degrees, i = 1 .. kSphereStacks - 1, plus the two poles.
inline constexpr int kSphereStacks = 8;

struct SphereSolid {
    RoundFrame f;
    double slope[3];  ///< du_k / dx along every row

    static SphereSolid from(const Primitive& p) {
        SphereSolid s{RoundFrame::from(p), {}};
        for (int k = 0; k < 3; ++k) s.slope[k] = s.f.slope(k);
        return s;
    }
    bool valid() const { return f.valid(); }
    double cx() const { return f.cx(); }
    /// World-space half extent of the ellipsoid's bounding box along grid axis j.
    double reach(int j) const {
        const BoxFrame& b = f.box;
        return std::sqrt(b.a[0][j] * b.a[0][j] * b.h[0] * b.h[0] + b.a[1][j] * b.a[1][j] * b.h[1] * b.h[1] +
                         b.a[2][j] * b.a[2][j] * b.h[2] * b.h[2]);
    }
    /// Offsets x - c.x inside the ellipsoid on row (y, z).
    Chord chord(double y, double z) const {
        const double at[3] = {f.atCentre(0, y, z), f.atCentre(1, y, z), f.atCentre(2, y, z)};
        return ellipseChord(slope, at);
    }
    /// The voxel-centre test: is point (x, y, z) inside the closed ellipsoid? (Never, if not valid().)
    bool contains(double x, double y, double z) const { return valid() && chord(y, z).contains(x - cx()); }
};

struct SphereKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Sphere;
    static constexpr std::string_view keyword = "sphere";
    template <class Args>
    static void parseArguments(Args&) {}
    template <class Args>
    static void emit(Primitive&, const Args&) {}
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        voxelizeChords(SphereSolid::from(p), rows, counts);
    }

    template <class Builder>
    static void outline(Builder& builder, const typename Builder::LocalMap& map, const Primitive& p, Outline& out) {
        using Homogeneous = typename Builder::Homogeneous;
        // In the primitive's own frame the solid is the unit ball. The contact curve seen from the
        // homogeneous eye (e, ew) (ew = 1: a point; ew = 0: parallel rays along e) is the circle
        // u . e = ew on the unit sphere.
        const glm::dvec3 clipNormal(map.m[3][0], map.m[3][1], map.m[3][2]);
        const bool inFront = map.m[3][3] - glm::length(clipNormal) >= 0.0;
        const bool solid = p.half.x != 0.0f && p.half.y != 0.0f && p.half.z != 0.0f;
        glm::dvec3 e(0.0);
        double ew = 0.0;
        const bool eye = builder.localEye(map, e, ew);
        const double len = glm::length(e);
        if (!inFront || !solid || !eye || !(len > ew)) {
            builder.addConvex(map, builder.uvSphereShape(), out);
            return;
        }
        const glm::dvec3 n = e / len;
        const double offset = ew / len, radius = std::sqrt(1.0 - offset * offset);
        const glm::dvec3 axis = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? glm::dvec3(1, 0, 0)
                                : std::fabs(n.y) <= std::fabs(n.z)                                   ? glm::dvec3(0, 1, 0)
                                                                                                     : glm::dvec3(0, 0, 1);
        const glm::dvec3 a = glm::normalize(glm::cross(n, axis)), b = glm::cross(n, a);
        // h(k) = map(centre) + cos_k * map'(radius a) + sin_k * map'(radius b), map' the linear part
        const Homogeneous hc = map.apply(offset * n);
        const glm::dvec3 ra = radius * a, rb = radius * b;
        Homogeneous ha{}, hb{};
        double* pa = &ha.x;
        double* pb = &hb.x;
        for (int r = 0; r < 4; ++r) {
            pa[r] = map.m[r][0] * ra.x + map.m[r][1] * ra.y + map.m[r][2] * ra.z;
            pb[r] = map.m[r][0] * rb.x + map.m[r][1] * rb.y + map.m[r][2] * rb.z;
        }
        const std::vector<glm::dvec2>& ring = builder.sphereRing();
        auto point = [&](int k) {
            const glm::dvec2 cs = ring[std::size_t(k)];
            return Homogeneous{hc.x + cs.x * ha.x + cs.y * hb.x, hc.y + cs.x * ha.y + cs.y * hb.y,
                               hc.w + cs.x * ha.w + cs.y * hb.w, hc.clip + cs.x * ha.clip + cs.y * hb.clip};
        };
        const int level = detailLevel(Builder::projectedRadius(hc, ha, hb), kSphereLevelRadius);
        const int points = kSphereSides >> level;
        const std::size_t first = out.points.size();
        out.points.resize(first + std::size_t(points));
        FixedPoint* pts = out.points.data() + first;
        bool fast = true;
        for (int k = 0; k < points && fast; ++k) {
            const Homogeneous q = point(k << level);
            const double inv = 1.0 / q.w, x = q.x * inv, y = q.y * inv;
            fast = builder.insideGuard(x, y);
            if (fast) pts[k] = snapToFixed(x, y);
        }
        if (fast) {
            out.pieces.push_back({std::uint32_t(first), std::uint32_t(points), 1, std::uint16_t(points)});
            builder.setLastRoundPoints(points);
            return;
        }
        // Reaching beyond the guard band: every point, clipped
        auto& h = builder.homogeneousScratch();
        h.resize(kSphereSides);
        for (int k = 0; k < kSphereSides; ++k) h[std::size_t(k)] = point(k);
        out.points.resize(first);
        builder.addClippedPiece(h.data(), h.size(), true, out);
    }

    static void surface(SurfaceBuilder& s, const Primitive&, const std::vector<MeshShape>*) {
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
};

}  // namespace shapevo
