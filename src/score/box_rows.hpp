// BoxFrame: an oriented box in double precision, the voxel-centre inside test that defines
// "covered", and the exact per-row x-interval of covered voxel centres.
//
// Exactness: along a row (fixed y, z) slab k's test is |a*(x - cx) + b| <= h with b fixed, and
// x_i = origin + (i + 0.5) * voxel. Every step is a monotone floating-point function of i, so
// the covered indices form one interval per slab; the closed-form bounds are used where they are
// provably far from an integer, and the test itself decides the rest. So the interval always
// equals what the brute-force test gives voxel by voxel, bit for bit.
#pragma once
#include <cmath>
#include <cstdint>

#include "geometry/primitive.hpp"
#include "score/volume_target.hpp"

namespace shapevo {

struct BoxFrame {
    double c[3];
    double a[3][3];  ///< a[k] = unit axis k
    double h[3];

    static BoxFrame from(const Primitive& p) {
        BoxFrame b{};
        for (int j = 0; j < 3; ++j) {
            b.c[j] = p.centre[j];
            b.h[j] = p.half[j];
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

/// Per-box constants of slab k along x, computed once per primitive.
struct SlabAlongX {
    double a;         ///< the slab normal's x component
    double base;      ///< index coordinate of the box centre: (cx - origin) / voxel - 0.5
    double perIndex;  ///< 1 / (a * voxel): index units per unit of signed distance
    static SlabAlongX of(const BoxFrame& b, int k, const GridSpec& grid) {
        const double a = b.a[k][0];
        return {a, (b.c[0] - grid.origin[0]) / grid.voxelSize - 0.5, a != 0.0 ? 1.0 / (a * grid.voxelSize) : 0.0};
    }
};

/// Indices i in [lo, hi] of one row whose centres pass slab k; returns false if none.
/// Only i in [first, last] are considered.
inline bool slabInterval(const BoxFrame& b, int k, const SlabAlongX& s, double rowTermK, const GridSpec& grid,
                         long first, long last, long& lo, long& hi) {
    const double a = s.a;
    auto test = [&](long i) { return b.inSlab(k, grid.centre(0, i), rowTermK); };
    if (a == 0.0) {  // the test does not depend on x at all (0 * finite + t == t exactly)
        if (!(std::fabs(rowTermK) <= b.h[k])) return false;
        lo = first;
        hi = last;
        return true;
    }
    constexpr double kReliableSlope = 1e-3, kMargin = 1e-4;
    if (std::fabs(a) >= kReliableSlope) {
        const double t1 = s.base + (-b.h[k] - rowTermK) * s.perIndex;
        const double t2 = s.base + (b.h[k] - rowTermK) * s.perIndex;
        const double tl0 = std::min(t1, t2), th0 = std::max(t1, t2);
        if (!(th0 >= double(first) - 1.0 && tl0 <= double(last) + 1.0)) return false;
        const double tl = std::max(tl0, double(first) - 1.0), th = std::min(th0, double(last) + 1.0);
        const double cl = std::ceil(tl), fh = std::floor(th);
        lo = std::max(first, long(cl));
        hi = std::min(last, long(fh));
        if (cl - tl < kMargin || tl - (cl - 1.0) < kMargin) {  // close to an integer: let the test decide
            while (lo > first && test(lo - 1)) --lo;
            while (lo <= hi && !test(lo)) ++lo;
        }
        if (th - fh < kMargin || (fh + 1.0) - th < kMargin) {
            while (hi < last && test(hi + 1)) ++hi;
            while (hi >= lo && !test(hi)) --hi;
        }
        return lo <= hi;
    }
    // Nearly perpendicular to x: bisect on the monotone signed distance, using the test itself.
    const bool increasing = a > 0;
    auto above = [&](long i) {  // signed distance >= -h (increasing) or <= h (decreasing)
        const double d = a * (grid.centre(0, i) - b.c[0]) + rowTermK;
        return increasing ? d >= -b.h[k] : d <= b.h[k];
    };
    auto below = [&](long i) {
        const double d = a * (grid.centre(0, i) - b.c[0]) + rowTermK;
        return increasing ? d <= b.h[k] : d >= -b.h[k];
    };
    // first index where above() holds
    long l = first, r = last + 1;
    while (l < r) {
        const long m = l + (r - l) / 2;
        if (above(m)) r = m; else l = m + 1;
    }
    lo = l;
    // last index where below() holds
    l = first - 1;
    r = last;
    while (l < r) {
        const long m = l + (r - l + 1) / 2;
        if (below(m)) l = m; else r = m - 1;
    }
    hi = l;
    return lo <= hi;
}

}  // namespace shapevo
