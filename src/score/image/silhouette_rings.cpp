// OutlineBuilder's fast path for boxes, prisms, frusta and pyramids (two rings of corners, or a
// ring and an apex): decide which faces the eye sees, keep the corners where a seen face meets
// an unseen one (the silhouette), put them in loop order (one arc of each ring, joined at the
// ends), project and snap only those. The loop order is a hint: FixedHull checks it and falls
// back to a full hull of the same points when rounding disturbs it.
#include <algorithm>
#include <bit>
#include <cmath>

#include "score/image/silhouette_outline.hpp"

namespace shapevo {

namespace {

/// Bit k set if bit k or bit k - 1 (cyclically, over n bits) of s is set: for sides s, the
/// corners on them (corner k joins sides k - 1 and k).
std::uint32_t cornersOf(std::uint32_t s, int n, std::uint32_t all) { return (s | (s << 1) | (s >> (n - 1))) & all; }

/// The set bits of m (n cyclic bits) as one arc: first index and length. False if they form
/// several arcs.
bool arcOf(std::uint32_t m, int n, std::uint32_t all, int& first, int& length) {
    first = 0;
    length = std::popcount(m);
    if (m == all || m == 0) return true;
    const std::uint32_t starts = m & ~(((m << 1) | (m >> (n - 1))) & all);
    if (std::popcount(starts) != 1) return false;
    first = std::countr_zero(starts);
    return true;
}

}  // namespace

bool OutlineBuilder::addRingsFast(const LocalMap& map, const RingTable* chosen, double topScale, Outline& out) {
    int roundPoints = 0;
    if (!chosen) {  // round: the level of detail from the rings' pixel radii
        const double(*m)[4] = map.m;
        const Homogeneous a{m[0][0], m[1][0], m[2][0], 0.0}, b{m[0][2], m[1][2], m[2][2], 0.0};
        const Homogeneous bottom{m[0][3] - m[0][1], m[1][3] - m[1][1], m[2][3] - m[2][1], 0.0};
        double radius = projectedRadius(bottom, a, b);
        if (topScale > 0.0) {
            const Homogeneous top{m[0][3] + m[0][1], m[1][3] + m[1][1], m[2][3] + m[2][1], 0.0};
            const Homogeneous ta{a.x * topScale, a.y * topScale, a.w * topScale, 0.0}, tb{b.x * topScale, b.y * topScale, b.w * topScale, 0.0};
            radius = std::max(radius, projectedRadius(top, ta, tb));
        }
        const int level = detailLevel(radius, kRingLevelRadius);
        chosen = &roundRings_[level];
        roundPoints = kRoundSides >> level;
    }
    const RingTable& table = *chosen;
    const int n = int(table.corners.size());
    // Everything in front of the clip plane? Bounded over the circle through the corners.
    const double* clip = map.m[3];
    const double clipXZ = std::sqrt(clip[0] * clip[0] + clip[2] * clip[2]) * table.reach;
    if (!(clip[3] - clip[1] - clipXZ >= 0.0) || !(clip[3] + clip[1] - topScale * clipXZ >= 0.0)) return false;
    glm::dvec3 e;
    double ew;
    if (!localEye(map, e, ew)) return false;

    // Facing: > 0 seen, < 0 unseen. Side k of a frustum with apothem a has the outward normal
    // (2 n_k.x, (1 - t) a, 2 n_k.z) and offset a (1 + t) (t = topScale); caps: u.y = -1 and 1.
    const double a = table.apothem;
    const double sideOffset = (1.0 - topScale) * a * e.y - a * (1.0 + topScale) * ew;
    std::uint32_t seen = 0, unseen = 0;
    for (int k = 0; k < n; ++k) {
        const double f = 2.0 * (table.normals[std::size_t(k)].x * e.x + table.normals[std::size_t(k)].y * e.z) + sideOffset;
        seen |= std::uint32_t(f >= 0.0) << k;
        unseen |= std::uint32_t(f <= 0.0) << k;
    }
    const std::uint32_t all = n == 32 ? ~0u : (1u << n) - 1;
    auto silhouette = [&](double cap) {
        const std::uint32_t s = cornersOf(seen, n, all) | (cap >= 0.0 ? all : 0u);
        const std::uint32_t u = cornersOf(unseen, n, all) | (cap <= 0.0 ? all : 0u);
        return s & u;
    };
    const std::uint32_t bottom = silhouette(-e.y - ew);
    const std::uint32_t top = topScale > 0.0 ? silhouette(e.y - ew) : 0u;
    const bool apex = topScale <= 0.0 && seen != 0 && unseen != 0;

    // Loop order: the bottom arc forwards, then the top arc from the end where the bottom arc
    // stopped, then the apex.
    loop_.clear();
    auto corner = [&](int k, double radius, double y) {
        const glm::dvec2& c = table.corners[std::size_t(k)];
        loop_.push_back({radius * c.x, y, radius * c.y});
    };
    int b0, bn, t0, tn;
    if (arcOf(bottom, n, all, b0, bn) && arcOf(top, n, all, t0, tn)) {
        int k = b0;
        for (int i = 0; i < bn; ++i, k = k + 1 == n ? 0 : k + 1) corner(k, 1.0, -1.0);
        const int bEnd = k == 0 ? n - 1 : k - 1;
        const int tEnd = t0 + tn - 1 >= n ? t0 + tn - 1 - n : t0 + tn - 1;
        if (bn == 0 || t0 == bEnd) {
            k = t0;
            for (int i = 0; i < tn; ++i, k = k + 1 == n ? 0 : k + 1) corner(k, topScale, 1.0);
        } else {
            k = tEnd;
            for (int i = 0; i < tn; ++i, k = k == 0 ? n - 1 : k - 1) corner(k, topScale, 1.0);
        }
    } else {  // several arcs (only when faces are within rounding of edge-on): no order
        for (int k = 0; k < n; ++k)
            if (bottom >> k & 1) corner(k, 1.0, -1.0);
        for (int k = 0; k < n; ++k)
            if (top >> k & 1) corner(k, topScale, 1.0);
    }
    if (apex) loop_.push_back({0.0, 1.0, 0.0});

    const std::size_t first = out.points.size();
    const double(*m)[4] = map.m;
    for (const glm::dvec3& u : loop_) {
        const double hw = m[2][0] * u.x + m[2][1] * u.y + m[2][2] * u.z + m[2][3], inv = 1.0 / hw;
        const double x = (m[0][0] * u.x + m[0][1] * u.y + m[0][2] * u.z + m[0][3]) * inv;
        const double y = (m[1][0] * u.x + m[1][1] * u.y + m[1][2] * u.z + m[1][3]) * inv;
        if (!insideGuard(x, y)) {
            out.points.resize(first);
            return false;
        }
        out.points.push_back(snapToFixed(x, y));
    }
    const auto count = std::uint32_t(loop_.size());
    out.pieces.push_back({std::uint32_t(first), count, 1, std::uint16_t(count)});
    lastRoundPoints_ = roundPoints;
    return true;
}

}  // namespace shapevo
