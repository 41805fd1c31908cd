// The Cylinder kind: `cylinder` in a grammar (no arguments). Solid u.x^2 + u.z^2 <= 1, |u.y| <= 1
// (axis = local y): CylinderSolid, its voxel-centre inside test and the chord of a voxel row, the
// elliptic disc's chord intersected with the end caps' slab (shape/chord_rows.hpp explains why
// this makes the row interval exact). Silhouette: the kRoundSides-gon prism (round two-ring fast
// path, else all its vertices). Surface: the prism, 2 * kRoundSides vertices.
#pragma once
#include <cmath>
#include <string_view>
#include <vector>

#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

struct CylinderSolid {
    RoundFrame f;
    double radialSlope[2];  ///< du_x / dx and du_z / dx along every row
    double axialSlope;      ///< du_y / dx

    static CylinderSolid from(const Primitive& p) {
        CylinderSolid s{RoundFrame::from(p), {}, 0.0};
        s.radialSlope[0] = s.f.slope(0);
        s.radialSlope[1] = s.f.slope(2);
        s.axialSlope = s.f.slope(1);
        return s;
    }
    bool valid() const { return f.valid(); }
    double cx() const { return f.cx(); }
    /// World-space half extent of the cylinder's bounding box along grid axis j.
    double reach(int j) const { return std::fabs(f.box.a[1][j]) * f.box.h[1] + f.ellipseReach(0, 2, j); }
    /// Offsets x - c.x inside the cylinder on row (y, z).
    Chord chord(double y, double z) const {
        const Chord caps = slabChord(axialSlope, f.atCentre(1, y, z));
        if (caps.empty()) return caps;
        const double at[2] = {f.atCentre(0, y, z), f.atCentre(2, y, z)};
        return caps & ellipseChord(radialSlope, at);
    }
    /// The voxel-centre test: is point (x, y, z) inside the closed cylinder? (Never, if not valid().)
    bool contains(double x, double y, double z) const { return valid() && chord(y, z).contains(x - cx()); }
};

struct CylinderKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Cylinder;
    static constexpr std::string_view keyword = "cylinder";
    template <class Args>
    static void parseArguments(Args&) {}
    template <class Args>
    static void emit(Primitive&, const Args&) {}
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        voxelizeChords(CylinderSolid::from(p), rows, counts);
    }
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive&, Outline& out) {
        if (!b.addRingsFast(map, nullptr, 1.0, out)) b.addConvex(map, b.prismShape(), out);
    }
    static void surface(SurfaceBuilder& s, const Primitive&, const std::vector<MeshShape>*) { frustumSurface(s, 1.0f); }
    /// Textures: its sides are mapped cylindrically at this mean radius (geometry/texture_uv.hpp).
    static float textureRadius(const Primitive& p) { return meanCrossRadius(p); }
};

}  // namespace shapevo
