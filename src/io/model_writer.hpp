// Model writers: a model's primitives as a triangle mesh in OBJ or PLY (binary little endian).
// Boxes become 8 vertices and 12 outward-facing triangles (mirrored frames keep their winding).
#pragma once
#include <string>

#include "geometry/primitive.hpp"
#include "io/mesh.hpp"

namespace shapevo {

/// Triangulate every primitive into one mesh.
Mesh meshOf(const Geometry& geometry);
void writeObj(const Mesh& mesh, const std::string& path);
void writePly(const Mesh& mesh, const std::string& path);

}  // namespace shapevo
