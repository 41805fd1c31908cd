// analyseMesh: exact welding, then edge use counts over a hash map; holes (the open-edge graph's
// independent cycles) and components by union-find over vertices.
#include "mesh/mesh_defects.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "mesh/mesh_formats.hpp"

namespace shapevo {

namespace {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    std::uint32_t find(std::uint32_t a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    void join(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

private:
    std::vector<std::uint32_t> parent_;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return std::uint64_t(a) << 32 | b;
}

struct TriangleKeyHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& t) const {
        return std::hash<std::uint64_t>()(std::uint64_t(t[0]) << 42 ^ std::uint64_t(t[1]) << 21 ^ t[2]);
    }
};

}  // namespace

MeshDefects analyseMesh(const Mesh& mesh, WeldedMesh* weldedOut) {
    MeshDefects d;
    d.triangles = mesh.triangles.size();
    Mesh welded;
    meshio::VertexWelder welder(welded);
    std::vector<std::uint32_t> canon(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) canon[i] = welder.add(mesh.vertices[i]);
    d.seamVertices = mesh.vertices.size() - welded.vertices.size();

    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(mesh.triangles.size());
    std::unordered_set<std::array<std::uint32_t, 3>, TriangleKeyHash> seen;
    seen.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const std::array<std::uint32_t, 3> c{canon.at(t[0]), canon.at(t[1]), canon.at(t[2])};
        const glm::vec3 &a = welded.vertices[c[0]], &b = welded.vertices[c[1]], &p = welded.vertices[c[2]];
        const double area = 0.5 * double(glm::length(glm::cross(b - a, p - a)));
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2] || !(area > 0.0)) {
            ++d.degenerateTriangles;
            continue;
        }
        std::array<std::uint32_t, 3> key = c;
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second) {
            ++d.duplicateTriangles;
            continue;
        }
        d.surfaceArea += area;
        kept.push_back(c);
    }

    std::unordered_map<std::uint64_t, std::uint32_t> uses;
    uses.reserve(kept.size() * 2);
    UnionFind pieces(welded.vertices.size());
    for (const auto& t : kept)
        for (int e = 0; e < 3; ++e) {
            ++uses[edgeKey(t[e], t[(e + 1) % 3])];
            pieces.join(t[e], t[(e + 1) % 3]);
        }
    UnionFind loops(welded.vertices.size());
    std::vector<std::uint32_t> borderVertices;
    for (const auto& [key, count] : uses) {
        if (count == 1) {
            ++d.openEdges;
            const auto a = std::uint32_t(key >> 32), b = std::uint32_t(key & 0xffffffffu);
            loops.join(a, b);
            borderVertices.push_back(a);
            borderVertices.push_back(b);
        } else if (count > 2) {
            ++d.nonManifoldEdges;
        }
    }
    // Border loops: the independent cycles of the open-edge graph (edges - vertices + pieces),
    // so two holes that touch at a vertex still count as two.
    std::sort(borderVertices.begin(), borderVertices.end());
    std::unordered_set<std::uint32_t> roots;
    for (std::uint32_t v : borderVertices) roots.insert(loops.find(v));
    const std::size_t distinct = std::size_t(std::unique(borderVertices.begin(), borderVertices.end()) - borderVertices.begin());
    d.holes = d.openEdges + roots.size() - distinct;
    roots.clear();
    for (const auto& t : kept) roots.insert(pieces.find(t[0]));
    d.components = roots.size();

    if (weldedOut) {
        weldedOut->vertices = std::move(welded.vertices);
        weldedOut->triangles = std::move(kept);
    }
    return d;
}

}  // namespace shapevo
