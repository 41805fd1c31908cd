// GLB writer: a triangle mesh as binary glTF 2.0 (one buffer, one mesh, one node, one scene),
// the format Blender, three.js and most viewers import directly. The buffer holds the vertex
// positions (float VEC3, with the min/max glTF requires) and then the triangle indices (uint32);
// there are no normals, so viewers shade the triangles flat, as glTF prescribes. Coordinates are
// written as they are (glTF's +y is up, as in shapevo's grammars).
#pragma once
#include <string>

#include "mesh/mesh.hpp"

namespace shapevo {

/// Writes `mesh` to `path` atomically (temporary file, then rename). An empty mesh gives a
/// valid file with one empty node and no buffer.
/// @throw InputError naming `path` if it cannot be written or the mesh holds a non-finite
///        coordinate or a vertex index out of range.
void writeGlb(const Mesh& mesh, const std::string& path);

}  // namespace shapevo
