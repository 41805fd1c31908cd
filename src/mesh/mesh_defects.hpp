// Mesh defects: what keeps a triangle mesh from bounding a volume. analyseMesh welds vertices at
// equal positions (seams), drops degenerate and duplicated triangles, and counts open edges, the
// border loops they form (holes), non-manifold edges and connected pieces. It changes nothing;
// mesh/mesh_repair.hpp fills what it finds.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace shapevo {

struct MeshDefects {
    std::size_t triangles = 0;            ///< triangles as read
    std::size_t seamVertices = 0;         ///< vertices that repeat an earlier vertex's position (merged)
    std::size_t degenerateTriangles = 0;  ///< two corners at one position, or zero area
    std::size_t duplicateTriangles = 0;   ///< the same three corners as an earlier triangle (any order)
    std::size_t openEdges = 0;            ///< edges of exactly one triangle
    std::size_t holes = 0;                ///< border loops: independent cycles of open edges (loops touching at a vertex count apart)
    std::size_t nonManifoldEdges = 0;     ///< edges of three or more triangles
    std::size_t components = 0;           ///< pieces connected through shared edges
    double surfaceArea = 0.0;             ///< of the kept triangles
    bool closed() const { return openEdges == 0; }
};

/// The mesh as analyseMesh sees it: one vertex per distinct position, and the triangles that
/// are neither degenerate nor repeats, in their original order and winding.
struct WeldedMesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Counts `mesh`'s defects (vertex indices must be in range). Positions are equal when their
/// coordinates are (-0 == +0). Edges are counted on the welded, kept triangles, so a seam of
/// duplicated vertices is no open edge and a doubled face no non-manifold one.
/// @param welded if not null, receives the welded mesh the counts describe.
MeshDefects analyseMesh(const Mesh& mesh, WeldedMesh* welded = nullptr);

}  // namespace shapevo
