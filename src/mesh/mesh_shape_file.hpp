// loadMeshShape: reads a closed OBJ/PLY/STL mesh for a `mesh "file"` grammar statement and
// normalizes it to [-1, 1]^3 (each axis scaled separately; a flat axis stays 0).
#pragma once
#include <string>

#include "mesh/mesh_shape.hpp"

namespace shapevo {

/// @throw InputError naming `path` when the file is unreadable, malformed or not closed.
MeshShape loadMeshShape(const std::string& path);

}  // namespace shapevo
