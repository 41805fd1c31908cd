// Adjacency components (adjacency.hpp): 4 edges per scope, a sweep over their tolerance boxes
// along x, the exact edge test on each candidate pair, union-find with the smaller index as root.
#include "geometry/lists/adjacency.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace shapevo::lists {
namespace {

double distanceToLine(const glm::dvec3& p, const glm::dvec3& origin, const glm::dvec3& direction) {
    const glm::dvec3 d = p - origin;
    return glm::length(d - direction * glm::dot(d, direction));
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];  // path halving
        i = parent[i];
    }
    return i;
}

}  // namespace

bool edgesShareSegment(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& b0, const glm::dvec3& b1, double tolerance) {
    const double la = glm::length(a1 - a0), lb = glm::length(b1 - b0);
    if (!(la > tolerance) || !(lb > tolerance)) return false;
    const glm::dvec3 da = (a1 - a0) / la, db = (b1 - b0) / lb;
    if (!(distanceToLine(b0, a0, da) <= tolerance && distanceToLine(b1, a0, da) <= tolerance &&
          distanceToLine(a0, b0, db) <= tolerance && distanceToLine(a1, b0, db) <= tolerance))
        return false;
    const double s0 = glm::dot(b0 - a0, da), s1 = glm::dot(b1 - a0, da);
    const double overlap = std::min(la, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1));
    return overlap > tolerance;
}

void rectangleCorners(const Scope& s, glm::dvec3 (&corners)[4]) {
    const glm::dvec3 origin(s.origin), x = glm::dvec3(s.axes[0]) * (0.5 * double(s.size.x)),
                                       y = glm::dvec3(s.axes[1]) * (0.5 * double(s.size.y));
    corners[0] = origin - x - y;
    corners[1] = origin + x - y;
    corners[2] = origin + x + y;
    corners[3] = origin - x + y;
}

void unifyAdjacent(std::span<const Scope> scopes, double tolerance, Grouping& out, ListWorkspace& ws) {
    const std::uint32_t n = std::uint32_t(scopes.size()), edges = 4 * n;
    // Edge end points (2 per edge) and boxes (min x y z, max x y z per edge), grown by the tolerance.
    ws.points.resize(2 * std::size_t(edges));
    ws.numbers.resize(6 * std::size_t(edges));
    glm::dvec3 corners[4];
    for (std::uint32_t i = 0; i < n; ++i) {
        rectangleCorners(scopes[i], corners);
        for (std::uint32_t e = 0; e < 4; ++e) {
            const std::uint32_t id = 4 * i + e;
            const glm::dvec3 p = corners[e], q = corners[(e + 1) % 4];
            ws.points[2 * id] = p;
            ws.points[2 * id + 1] = q;
            for (int a = 0; a < 3; ++a) {
                ws.numbers[6 * id + a] = std::min(p[a], q[a]) - tolerance;
                ws.numbers[6 * id + 3 + a] = std::max(p[a], q[a]) + tolerance;
            }
        }
    }
    const double* box = ws.numbers.data();
    ws.indices2.resize(edges);
    for (std::uint32_t e = 0; e < edges; ++e) ws.indices2[e] = e;
    // Boxes with a NaN sort last and never overlap anything (comparisons with NaN are false).
    std::sort(ws.indices2.begin(), ws.indices2.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double xa = box[6 * a], xb = box[6 * b];
        if (xa < xb) return true;
        if (xb < xa) return false;
        const bool nanA = std::isnan(xa), nanB = std::isnan(xb);
        if (nanA != nanB) return nanB;
        return a < b;
    });
    std::vector<std::uint32_t>& parent = ws.labels;
    parent.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
    for (std::uint32_t s = 0; s < edges; ++s) {
        const std::uint32_t a = ws.indices2[s];
        const double* boxA = box + 6 * std::size_t(a);
        for (std::uint32_t t = s + 1; t < edges; ++t) {
            const std::uint32_t b = ws.indices2[t];
            const double* boxB = box + 6 * std::size_t(b);
            if (!(boxB[0] <= boxA[3])) break;  // sorted by min x: no later box reaches a's x range
            if (a / 4 == b / 4 || boxB[1] > boxA[4] || boxA[1] > boxB[4] || boxB[2] > boxA[5] || boxA[2] > boxB[5]) continue;
            const std::uint32_t ra = findRoot(parent, a / 4), rb = findRoot(parent, b / 4);
            if (ra == rb) continue;
            const std::uint32_t first = std::min(a, b), second = std::max(a, b);  // the test's order: by edge id
            if (!edgesShareSegment(ws.points[2 * first], ws.points[2 * first + 1], ws.points[2 * second],
                                   ws.points[2 * second + 1], tolerance))
                continue;
            parent[std::max(ra, rb)] = std::min(ra, rb);
        }
    }
    ws.indices.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) ws.indices[i] = findRoot(parent, i);
    groupFromLabels(ws.indices, n, out, ws);
}

}  // namespace shapevo::lists
