// SphereSolid: the Sphere primitive (an ellipsoid |u| <= 1 filling its frame's box), its voxel
// centre inside test and the chord of a voxel row (chord_rows.hpp explains why the test is
// written per row and why that makes the row interval exact).
#pragma once
#include <cmath>

#include "score/chord_rows.hpp"

namespace shapevo {

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

}  // namespace shapevo
