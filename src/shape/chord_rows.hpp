// Chords: the shared machinery of the round kinds (cylinder, cone, sphere in shape/kinds/): their
// row test, its exact index interval, and the voxelizing loop over a round solid's rows. A round solid's inside test is written per voxel row: the row's line (fixed y, z,
// running along the grid's x axis) is intersected with the solid in the frame's local
// coordinates, which gives a closed interval of x offsets from the solid's centre, the chord;
// a point is inside iff its offset x - c.x lies in the chord of its row.
//
// In exact arithmetic that is the definition in shape/primitive.hpp; in doubles it differs
// from evaluating the quadric at the point only within rounding of the surface (the tests check
// it against the textbook formula in long double). What writing it this way buys: along a row
// the test is "lo <= x_i - c.x <= hi" with lo, hi fixed and x_i increasing in i, so the voxels
// inside form one index interval, and chordInterval finds its ends exactly (an estimate fixed up
// with the test itself). A direct quadric evaluation is not monotone in floating point: on rows
// grazing the surface it can flicker in, out, in, and no interval would match it.
#pragma once
#include <algorithm>
#include <cmath>

#include "shape/box_frame.hpp"

namespace shapevo {

/// A closed interval of x offsets [lo, hi]; empty unless lo <= hi (so NaN means empty). Ends
/// may be infinite (a row along the axis of an infinite cylinder, a slab parallel to x).
struct Chord {
    double lo, hi;
    static constexpr Chord all() { return {-INFINITY, INFINITY}; }
    static constexpr Chord none() { return {INFINITY, -INFINITY}; }
    bool empty() const { return !(lo <= hi); }
    bool contains(double dx) const { return lo <= dx && dx <= hi; }
    Chord operator&(const Chord& o) const {
        if (empty() || o.empty()) return none();  // also keeps a NaN from being dropped by max/min
        return {std::max(lo, o.lo), std::min(hi, o.hi)};
    }
};

/// A round primitive's frame in double precision. Local coordinates: u_k = d_k / h_k with d_k the
/// signed distance along axis k (the same expression as BoxFrame), so along a row
/// u_k(dx) = slope(k) * dx + atCentre(k, y, z), dx = x - c.x.
struct RoundFrame {
    BoxFrame box;   ///< centre, axes and |half extents|
    double inv[3];  ///< 1 / h

    static RoundFrame from(const Primitive& p) {
        RoundFrame f{BoxFrame::from(p), {}};
        for (int k = 0; k < 3; ++k) f.inv[k] = 1.0 / f.box.h[k];
        return f;
    }
    /// Finite, with three positive half extents: a round solid with a zero half extent has no
    /// volume and covers no voxel centre.
    bool valid() const {
        if (!box.finite()) return false;
        for (int k = 0; k < 3; ++k)
            if (!(box.h[k] > 0.0) || !std::isfinite(inv[k])) return false;
        return true;
    }
    double cx() const { return box.c[0]; }
    /// du_k / dx along a row.
    double slope(int k) const { return box.a[k][0] * inv[k]; }
    /// u_k at x = c.x on row (y, z).
    double atCentre(int k, double y, double z) const { return box.rowTerm(k, y, z) * inv[k]; }
    /// Half extent of the elliptic cross-section spanned by local axes k and l, seen along grid axis j.
    double ellipseReach(int k, int l, int j) const {
        return std::hypot(box.a[k][j] * box.h[k], box.a[l][j] * box.h[l]);
    }
};

/// The point of a row closest to a round solid's axis (the frame's local y): its offset `mid`
/// from the row's x = c.x and the radial coordinates u.x, u.z there. Round kinds whose lateral
/// surface is a quadratic along the row (cone, paraboloid) set the quadratic up around this
/// point, so its coefficients stay small and nothing cancels.
struct AxisNearest {
    double mid, ux, uz;
};
/// `radialSlope` are du.x / dx and du.z / dx along every row, `radialSq` their squared length;
/// bx, bz are u.x and u.z at x = c.x on the row.
inline AxisNearest nearestToAxis(const double (&radialSlope)[2], double radialSq, double bx, double bz) {
    const double mid = radialSq > 0.0 ? -(radialSlope[0] * bx + radialSlope[1] * bz) / radialSq : 0.0;
    return {mid, radialSlope[0] * mid + bx, radialSlope[1] * mid + bz};
}

/// Offsets dx with |slope * dx + at| <= 1 (a slab: |u| <= 1 along one local axis).
inline Chord slabChord(double slope, double at) {
    if (slope == 0.0) return std::fabs(at) <= 1.0 ? Chord::all() : Chord::none();
    const double a = (-1.0 - at) / slope, b = (1.0 - at) / slope;
    return {std::min(a, b), std::max(a, b)};
}

/// Offsets dx with sum_k (slope_k * dx + at_k)^2 <= 1 over n local axes (a disc or a ball).
/// Written around the point of the line closest to the local origin, so nothing cancels.
template <int n>
Chord ellipseChord(const double (&slope)[n], const double (&at)[n]) {
    double ss = 0.0, sa = 0.0;
    for (int k = 0; k < n; ++k) {
        ss += slope[k] * slope[k];
        sa += slope[k] * at[k];
    }
    if (ss == 0.0) {  // the row runs along the axis: inside everywhere or nowhere
        double aa = 0.0;
        for (int k = 0; k < n; ++k) aa += at[k] * at[k];
        return aa <= 1.0 ? Chord::all() : Chord::none();
    }
    const double mid = -sa / ss;
    double m2 = 0.0;  // squared distance of the closest point from the axis
    for (int k = 0; k < n; ++k) {
        const double u = slope[k] * mid + at[k];
        m2 += u * u;
    }
    if (!(m2 <= 1.0)) return Chord::none();
    const double w = std::sqrt((1.0 - m2) / ss);
    return {mid - w, mid + w};
}

/// Smallest i in [first, last + 1] with pred(i) (last + 1 if none), for a predicate that is
/// false and then true along the row. `guess` (a real index; may be infinite or NaN) only
/// says where to start; the answer is found by testing pred itself, so it is exact.
template <class Pred>
long firstTrue(long first, long last, double guess, Pred pred) {
    double g = std::ceil(guess);
    if (!(g >= double(first))) g = double(first);  // NaN too
    if (g > double(last + 1)) g = double(last + 1);
    long i = long(g);
    if (i > last || pred(i)) {
        while (i > first && pred(i - 1)) --i;
    } else {
        do ++i;
        while (i <= last && !pred(i));
    }
    return i;
}

/// Indices i in [first, last] whose voxel centre offset grid.centre(0, i) - cx lies in `ch`;
/// false if none. Exact: equal to testing Chord::contains on every index.
inline bool chordInterval(const Chord& ch, double cx, const GridSpec& grid, long first, long last, long& lo, long& hi) {
    if (ch.empty()) return false;
    // real index of a voxel centre at offset dx: (cx + dx - origin) / voxel - 0.5
    const double base = (cx - grid.origin[0]) / grid.voxelSize - 0.5, perUnit = 1.0 / grid.voxelSize;
    lo = firstTrue(first, last, base + ch.lo * perUnit, [&](long i) { return grid.centre(0, i) - cx >= ch.lo; });
    hi = firstTrue(first, last, base + ch.hi * perUnit, [&](long i) { return grid.centre(0, i) - cx > ch.hi; }) - 1;
    return lo <= hi;
}

/// Voxelize a round solid (CylinderSolid, ConeSolid, SphereSolid): every voxel row of its bounding
/// box gets its chord's exact index interval. `rows` is the voxelizer (score/volume/voxelizer.hpp; the
/// kinds' row interface: grid(), indexBounds(), addRow(), addRows()); `counts` its VoxelCounts.
template <class Solid, class Rows, class Counts>
void voxelizeChords(const Solid& s, Rows& rows, Counts& counts) {
    if (!s.valid()) return;
    const GridSpec& grid = rows.grid();
    const double reach[3] = {s.reach(0), s.reach(1), s.reach(2)};
    long first[3], last[3];
    if (!rows.indexBounds(s.f.box.c, reach, first, last)) return;
    for (long z = first[2]; z <= last[2]; ++z) {
        const double cz = grid.centre(2, z);
        for (long y = first[1]; y <= last[1]; ++y) {
            ++counts.rows;
            long lo, hi;
            if (chordInterval(s.chord(grid.centre(1, y), cz), s.cx(), grid, first[0], last[0], lo, hi))
                rows.addRow(y, z, lo, hi, counts);
        }
    }
}

}  // namespace shapevo
