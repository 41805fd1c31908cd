// Test reference for inside/outside of imperfect meshes: the generalized winding number (the
// signed solid angle the triangles subtend at a point, over 4 pi; Van Oosterom-Strackee per
// triangle), summed brute force over every triangle. About 1 inside a closed outward-wound
// mesh and 0 outside, and still close to that near small holes; a point is inside when > 0.5.
#pragma once
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace shapevo::test {

inline double windingNumber(const Mesh& mesh, const glm::dvec3& p) {
    double sum = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a = glm::dvec3(mesh.vertices[t[0]]) - p, b = glm::dvec3(mesh.vertices[t[1]]) - p,
                         c = glm::dvec3(mesh.vertices[t[2]]) - p;
        const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
        const double num = glm::dot(a, glm::cross(b, c));
        const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
        sum += 2.0 * std::atan2(num, den);
    }
    return sum / (4.0 * M_PI);
}

}  // namespace shapevo::test
