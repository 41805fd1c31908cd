// Mesh file input: reads OBJ, PLY (ascii, binary little-endian) and STL (ascii, binary) into a
// triangle Mesh, and checks that a mesh is closed before it is turned into a volume target.
#pragma once
#include <string>

#include "mesh/mesh.hpp"

namespace shapevo {

/// Reads a mesh, choosing the format by the file extension (.obj, .ply, .stl; any case).
/// Polygons are fan-triangulated. STL vertices are welded where positions are exactly equal.
/// @throw InputError naming the file (and line, or element index for binary data) when the file
///        cannot be opened, has an unknown extension, a malformed number, a face index out of
///        range, a face with fewer than 3 vertices, a non-finite coordinate, or no triangles.
Mesh readMesh(const std::string& path);

/// Throws InputError (naming `path`) unless every undirected edge is shared by exactly two
/// triangles, after merging vertices whose positions are exactly equal. The message says how
/// many edges are open and gives one of them by its end-point coordinates.
void requireClosed(const Mesh& mesh, const std::string& path);

}  // namespace shapevo
