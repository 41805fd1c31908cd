// Mesh: an indexed triangle mesh as read from OBJ/PLY/STL; input to target making.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace shapevo {

struct Mesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< faces are triangulated on read
};

}  // namespace shapevo
