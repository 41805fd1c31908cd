// loadMeshShape: mesh/mesh_reader does the reading and the closedness check; this file normalizes.
#include "mesh/mesh_shape_file.hpp"

#include <algorithm>

#include <glm/common.hpp>

#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"

namespace shapevo {

MeshShape loadMeshShape(const std::string& path) {
    Mesh m = readMesh(path);
    requireClosed(m, path);
    glm::vec3 lo = m.vertices.front(), hi = lo;
    for (const glm::vec3& v : m.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    // halves first: (lo + hi) overflows to infinity for a mesh far from the origin
    const glm::vec3 mid = lo * 0.5f + hi * 0.5f, halfExtent = hi * 0.5f - lo * 0.5f;
    if (!(std::max({halfExtent.x, halfExtent.y, halfExtent.z}) > 0.0f))
        throw InputError(path, "", "the mesh has no extent (all vertices are equal)");
    MeshShape s;
    s.path = path;
    s.vertices.reserve(m.vertices.size());
    for (const glm::vec3& v : m.vertices) {
        glm::vec3 u(0.0f);
        for (int j = 0; j < 3; ++j) u[j] = halfExtent[j] > 0.0f ? std::clamp((v[j] - mid[j]) / halfExtent[j], -1.0f, 1.0f) : 0.0f;
        s.vertices.push_back(u);
    }
    s.triangles = std::move(m.triangles);
    return s;
}

}  // namespace shapevo
