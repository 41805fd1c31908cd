// MeshShape: a closed triangle mesh used as a primitive (`mesh "leaf.obj"` in a grammar),
// normalized so that its bounding box is [-1, 1]^3; a Mesh primitive scales it to its frame.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace shapevo {

struct MeshShape {
    std::string path;                                        ///< the file it was read from, as written in the grammar
    std::vector<glm::vec3> vertices;                         ///< in [-1, 1]^3
    std::vector<std::array<std::uint32_t, 3>> triangles;     ///< outward-facing (counter-clockwise seen from outside)
};

}  // namespace shapevo
