// Test helpers for the io tests: an axis-aligned box as a closed, outward-wound triangle mesh
// (8 vertices, 12 triangles), and writing a test file into a TempDir.
#pragma once
#include <fstream>
#include <stdexcept>
#include <string>

#include "mesh/mesh.hpp"
#include "../test_support.hpp"

namespace shapevo::test {

/// Vertex i has x = hi.x if bit 0 of i is set (else lo.x), y from bit 1, z from bit 2.
inline Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    // Quads counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

inline Mesh cubeMesh(float halfSize) { return boxMesh(glm::vec3(-halfSize), glm::vec3(halfSize)); }

/// Writes `bytes` to `name` inside `dir` and returns the file's full path.
inline std::string writeFile(const TempDir& dir, const std::string& name, const std::string& bytes) {
    const std::string path = dir.file(name);
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error("cannot write " + path);
    return path;
}

}  // namespace shapevo::test
