// Test meshes with the defects real meshes have, built in code: a cube with subdivided faces
// (so single triangles can be cut out as small holes), a UV sphere whose seam and poles repeat
// vertices, a torus, and helpers to cut holes and double faces. All are outward-wound.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace shapevo::test {

/// The cube [-h, h]^3 with every face split into n x n quads (two triangles each), vertices
/// shared between faces (welded by construction), outward-wound.
inline Mesh gridCube(float h, int n) {
    Mesh m;
    auto vertex = [&](glm::vec3 p) {
        for (std::uint32_t i = 0; i < m.vertices.size(); ++i)
            if (m.vertices[i] == p) return i;
        m.vertices.push_back(p);
        return std::uint32_t(m.vertices.size() - 1);
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    std::uint32_t q[4];
                    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                    for (int k = 0; k < 4; ++k) {
                        glm::vec3 p(0.0f);
                        p[axis] = float(side) * h;
                        p[u] = -h + 2.0f * h * float(i + di[k]) / float(n);
                        p[v] = -h + 2.0f * h * float(j + dj[k]) / float(n);
                        q[k] = vertex(p);
                    }
                    // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
                    if (side > 0) {
                        m.triangles.push_back({q[0], q[1], q[2]});
                        m.triangles.push_back({q[0], q[2], q[3]});
                    } else {
                        m.triangles.push_back({q[0], q[2], q[1]});
                        m.triangles.push_back({q[0], q[3], q[2]});
                    }
                }
        }
    return m;
}

/// A UV sphere: (stacks + 1) x (slices + 1) vertices, so the seam column and each pole repeat
/// positions (a seam as exporters write it: equal positions, separate vertices).
inline Mesh seamSphere(float r, int stacks, int slices, glm::vec3 centre = glm::vec3(0.0f)) {
    Mesh m;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            const double th = M_PI * i / stacks, ph = 2.0 * M_PI * (j % slices) / slices;
            const double s = (i == 0 || i == stacks) ? 0.0 : std::sin(th);  // poles exactly on the axis
            m.vertices.push_back(centre + r * glm::vec3(float(s * std::cos(ph)), float(i == stacks ? -1.0 : std::cos(th)),
                                                        float(s * std::sin(ph))));
        }
    auto at = [&](int i, int j) { return std::uint32_t(i * (slices + 1) + j); };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
            if (i > 0) m.triangles.push_back({a, b, c});
            if (i + 1 < stacks) m.triangles.push_back({a, c, d});
        }
    return m;
}

/// A torus around the y axis (ring radius R, tube radius r), seamless, outward-wound.
inline Mesh torus(float R, float r, int around, int tube) {
    Mesh m;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const double a = 2.0 * M_PI * i / around, b = 2.0 * M_PI * j / tube;
            const double w = R + r * std::cos(b);
            m.vertices.push_back(glm::vec3(float(w * std::cos(a)), float(r * std::sin(b)), float(w * std::sin(a))));
        }
    auto at = [&](int i, int j) { return std::uint32_t((i % around) * tube + (j % tube)); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            m.triangles.push_back({a, d, c});
            m.triangles.push_back({a, c, b});
        }
    return m;
}

/// `mesh` without the triangles at the given indices.
inline Mesh withoutTriangles(Mesh mesh, std::vector<std::size_t> drop) {
    std::sort(drop.rbegin(), drop.rend());
    for (std::size_t t : drop) mesh.triangles.erase(mesh.triangles.begin() + std::ptrdiff_t(t));
    return mesh;
}

/// `a` and `b` in one mesh (b's vertices appended, not welded).
inline Mesh joined(Mesh a, const Mesh& b) {
    const auto offset = std::uint32_t(a.vertices.size());
    a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return a;
}

}  // namespace shapevo::test
