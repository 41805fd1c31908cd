// Model writers: a model's primitives as a triangle mesh in OBJ or PLY (binary little endian).
// Every primitive kind is tessellated as in geometry/tessellation.hpp (outward-facing, mirrored
// frames too); the files appear atomically (temporary file, then rename).
#pragma once
#include <string>

#include "shape/primitive.hpp"
#include "mesh/mesh.hpp"

namespace shapevo {

/// Triangulate every primitive into one mesh (tessellate()).
Mesh meshOf(const Geometry& geometry);
void writeObj(const Mesh& mesh, const std::string& path);
void writePly(const Mesh& mesh, const std::string& path);

}  // namespace shapevo
