// GLB writer: a triangle mesh as binary glTF 2.0 (one buffer, one mesh, one node, one scene),
// the format Blender, three.js and most viewers import directly. The buffer holds the vertex
// positions (float VEC3, with the min/max glTF requires) and then the triangle indices (uint32);
// there are no normals, so viewers shade the triangles flat, as glTF prescribes. Coordinates are
// written as they are (glTF's +y is up, as in shapevo's grammars).
// A mesh with materials (mesh/mesh.hpp) gets one glTF material per MeshMaterial, in order, with
// its `name` and pbrMetallicRoughness baseColorFactor [r, g, b, 1] in linear RGB (as glTF
// defines it; metallicFactor 0, roughness glTF's default 1), and one mesh primitive per material
// that has triangles: all share the POSITION accessor, each has its own index accessor into the
// one index buffer view, where each material's triangles follow one another in mesh order.
// Without materials there is one primitive with no material and the file holds nothing else.
// Textures (a mesh with UVs and textured materials): every primitive also has TEXCOORD_0 (float
// VEC2, one per vertex, glTF's v = 1 - the mesh's v, the accessor after the index accessors, in
// buffer view 2 after the indices), each MeshTexture is an image (mimeType image/png, its bytes
// embedded in the buffer after the UVs, one buffer view each) and a texture using the one
// sampler (linear filtering, REPEAT in s and t), and a textured material has baseColorFactor
// white times baseColorTexture {"index": its texture}.
#pragma once
#include <string>

#include "base/atomic_write.hpp"
#include "mesh/mesh.hpp"

namespace shapevo {

/// Writes `mesh` to `path` atomically (temporary file, then rename; with Replace::Never an
/// existing file is not replaced). An empty mesh gives a valid file with one empty node and
/// no buffer.
/// @throw InputError naming `path` if it cannot be written or the mesh holds a non-finite
///        coordinate, a vertex index out of range or inconsistent materials (checkMaterials()).
void writeGlb(const Mesh& mesh, const std::string& path, Replace replace = Replace::Always);

}  // namespace shapevo
