// BoxFrame: a primitive's oriented frame as a box in double precision (the Box kind's solid and
// the frame every other kind's solid is built on), the voxel-centre inside test that defines
// "covered" for a box, and the exact per-row x-interval of covered voxel centres of one slab.
//
// Exactness: along a row (fixed y, z) slab k's test is |a*(x - cx) + b| <= h with b fixed, and
// x_i = origin + (i + 0.5) * voxel. Every step is a monotone floating-point function of i, so
// the covered indices form one interval per slab; the closed-form bounds are used where they are
// provably far from an integer, and the test itself decides the rest. So the interval always
// equals what the brute-force test gives voxel by voxel, bit for bit.
#pragma once
#include <cmath>
#include <cstdint>

#include "shape/grid_spec.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

struct BoxFrame {
    double c[3];
    double a[3][3];  ///< a[k] = unit axis k
    double h[3];

    static BoxFrame from(const Primitive& p) {
        BoxFrame b{};
        for (int j = 0; j < 3; ++j) {
            b.c[j] = p.centre[j];
            b.h[j] = std::fabs(double(p.half[j]));  // a box is the same for +-h
            for (int k = 0; k < 3; ++k) b.a[j][k] = p.axes[j][k];
        }
        return b;
    }
    /// The y/z part of slab k's signed distance (the same expression the full test uses).
    double rowTerm(int k, double y, double z) const { return a[k][1] * (y - c[1]) + a[k][2] * (z - c[2]); }
    bool inSlab(int k, double x, double rowTermK) const { return std::fabs(a[k][0] * (x - c[0]) + rowTermK) <= h[k]; }
    /// The voxel-centre test: is point (x, y, z) inside the closed box?
    bool contains(double x, double y, double z) const {
        for (int k = 0; k < 3; ++k)
            if (!inSlab(k, x, rowTerm(k, y, z))) return false;
        return true;
    }
    /// World-space half extent of the box's bounding box along axis j.
    double reach(int j) const {
        return std::fabs(a[0][j]) * h[0] + std::fabs(a[1][j]) * h[1] + std::fabs(a[2][j]) * h[2];
    }
    bool finite() const {
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(c[j]) || !std::isfinite(h[j])) return false;
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(a[j][k])) return false;
        }
        return true;
    }
};

/// Slab k of a box seen along one grid axis: the test at index i is
/// |a * (centre(axis, i) - c) + t| <= h, with t the part of the distance that does not depend on i.
struct SlabLine {
    int axis;
    double a, c, h;
    double base;      ///< index coordinate of the box centre: (c - origin) / voxel - 0.5
    double perIndex;  ///< 1 / (a * voxel): index units per unit of signed distance
    static SlabLine of(const BoxFrame& b, int k, int axis, const GridSpec& grid) {
        const double a = b.a[k][axis];
        return {axis, a, b.c[axis], b.h[k], (b.c[axis] - grid.origin[axis]) / grid.voxelSize - 0.5,
                a != 0.0 ? 1.0 / (a * grid.voxelSize) : 0.0};
    }
    bool test(const GridSpec& grid, long i, double t) const {
        return std::fabs(a * (grid.centre(axis, i) - c) + t) <= h;
    }
};

/// Indices i in [lo, hi] within [first, last] that pass the slab test with offset t; false if none.
/// Exact: equals testing every index, because the signed distance is monotone in i.
inline bool slabInterval(const SlabLine& s, double t, const GridSpec& grid, long first, long last, long& lo, long& hi) {
    const double a = s.a;
    if (a == 0.0) {  // the test does not depend on i at all (0 * finite + t == t exactly)
        if (!(std::fabs(t) <= s.h)) return false;
        lo = first;
        hi = last;
        return true;
    }
    constexpr double kReliableSlope = 1e-3, kMargin = 1e-4;
    if (std::fabs(a) >= kReliableSlope) {
        const double t1 = s.base + (-s.h - t) * s.perIndex;
        const double t2 = s.base + (s.h - t) * s.perIndex;
        const double tl0 = std::min(t1, t2), th0 = std::max(t1, t2);
        if (!(th0 >= double(first) - 1.0 && tl0 <= double(last) + 1.0)) return false;
        const double tl = std::max(tl0, double(first) - 1.0), th = std::min(th0, double(last) + 1.0);
        const double cl = std::ceil(tl), fh = std::floor(th);
        lo = std::max(first, long(cl));
        hi = std::min(last, long(fh));
        if (cl - tl < kMargin || tl - (cl - 1.0) < kMargin) {  // close to an integer: let the test decide
            while (lo > first && s.test(grid, lo - 1, t)) --lo;
            while (lo <= hi && !s.test(grid, lo, t)) ++lo;
        }
        if (th - fh < kMargin || (fh + 1.0) - th < kMargin) {
            while (hi < last && s.test(grid, hi + 1, t)) ++hi;
            while (hi >= lo && !s.test(grid, hi, t)) --hi;
        }
        return lo <= hi;
    }
    // Nearly perpendicular to the axis: bisect on the monotone signed distance.
    const bool increasing = a > 0;
    auto distance = [&](long i) { return a * (grid.centre(s.axis, i) - s.c) + t; };
    auto above = [&](long i) { return increasing ? distance(i) >= -s.h : distance(i) <= s.h; };
    auto below = [&](long i) { return increasing ? distance(i) <= s.h : distance(i) >= -s.h; };
    long l = first, r = last + 1;  // first index where above() holds
    while (l < r) {
        const long m = l + (r - l) / 2;
        if (above(m)) r = m; else l = m + 1;
    }
    lo = l;
    l = first - 1;  // last index where below() holds
    r = last;
    while (l < r) {
        const long m = l + (r - l + 1) / 2;
        if (below(m)) l = m; else r = m - 1;
    }
    hi = l;
    return lo <= hi;
}

}  // namespace shapevo
