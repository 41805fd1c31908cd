// cornerBox: the axis-aligned box of the corners of a mesh's triangles. Vertices no triangle uses
// are left out, as a renderer and a voxelizer see the mesh. Used to frame a mesh (render), to size
// its voxels (shapevo target) and to scale a flatness test (volume targets).
#pragma once
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace shapevo {

struct CornerBox {
    glm::vec3 lo{std::numeric_limits<float>::max()};     ///< (FLT_MAX, ...) when the mesh has no triangle
    glm::vec3 hi{std::numeric_limits<float>::lowest()};  ///< (-FLT_MAX, ...) when the mesh has no triangle
};

/// The box of every triangle's corners; lo > hi when the mesh has no triangle.
inline CornerBox cornerBox(const Mesh& mesh) {
    CornerBox box;
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t) box.lo = glm::min(box.lo, mesh.vertices[i]), box.hi = glm::max(box.hi, mesh.vertices[i]);
    return box;
}

}  // namespace shapevo
