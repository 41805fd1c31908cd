// merge: corners of every member in the first member's frame, min / max per axis (merge.hpp).
#include "geometry/lists/merge.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace shapevo::lists {

void scopeCorners(const Scope& s, glm::dvec3 (&corners)[8]) {
    const glm::dvec3 origin(s.origin), half = glm::dvec3(s.size) * 0.5;
    const glm::dvec3 x(s.axes[0]), y(s.axes[1]), z(s.axes[2]);
    for (int c = 0; c < 8; ++c)
        corners[c] = origin + x * ((c & 1) ? half.x : -half.x) + y * ((c & 2) ? half.y : -half.y) +
                     z * ((c & 4) ? half.z : -half.z);
}

Scope mergeScopes(std::span<const Scope> members) {
    if (members.empty()) return Scope{glm::vec3(0.0f), glm::mat3(1.0f), glm::vec3(0.0f), 0};
    const Scope& first = members.front();
    const glm::dvec3 origin(first.origin);
    const glm::dvec3 axes[3] = {glm::dvec3(first.axes[0]), glm::dvec3(first.axes[1]), glm::dvec3(first.axes[2])};
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    glm::dvec3 corners[8];
    for (const Scope& m : members) {
        scopeCorners(m, corners);
        for (const glm::dvec3& c : corners)
            for (int a = 0; a < 3; ++a) {
                const double t = glm::dot(c - origin, axes[a]);
                lo[a] = std::min(lo[a], t);
                hi[a] = std::max(hi[a], t);
            }
    }
    const glm::dvec3 centre = (lo + hi) * 0.5;
    Scope out = first;
    out.origin = glm::vec3(origin + axes[0] * centre.x + axes[1] * centre.y + axes[2] * centre.z);
    out.size = glm::vec3(hi - lo);
    return out;
}

}  // namespace shapevo::lists
