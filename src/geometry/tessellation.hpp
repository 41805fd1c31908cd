// Tessellation: the surface of a primitive as outward-facing triangles in world coordinates, for
// exported meshes (OBJ, PLY, GLB). Each kind builds its piece (K::surface in shape/kinds/*.hpp)
// in the frame's unit coordinates u and SurfaceBuilder (shape/surface.hpp) places it with
// world = centre + axes * (half * u); frames with det(axes) < 0 (mirrored) get their triangles
// reversed so that they still face outwards.
//   Box       8 vertices, 12 triangles
//   Cylinder  a kRoundSides-gon prism: 2 * kRoundSides vertices, 4 * kRoundSides - 4 triangles
//   Cone      a kRoundSides-gon frustum like the cylinder; with taper 0 a pyramid with one apex
//             vertex: kRoundSides + 1 vertices, 2 * kRoundSides - 2 triangles
//   Sphere    a UV sphere of kRoundSides slices and kSphereStacks stacks (poles on the y axis)
//   Roof      the convex hull of the bottom square and the top rectangle: 8 vertices, 12
//             triangles; a ridge top (one fraction 0) 6 and 8, an apex (both 0) 5 and 6
//   Paraboloid the inscribed polyhedron of kParaboloidRings kRoundSides-gon rings and the apex:
//             kParaboloidRings * kRoundSides + 1 vertices, 2 * kParaboloidRings * kRoundSides - 2
//             triangles
//   Mesh      the grammar's mesh Geometry::meshes[mesh], vertex for vertex
// Every piece is closed: each edge is shared by exactly two triangles, in opposite directions.
// Looks: when the grammar set colours or materials (Geometry::appearance not empty), the mesh
// carries one MeshMaterial per distinct appearance (same colour after clamping to [0, 1], same
// material, same texture), in the order primitives first use them, and each triangle the material
// of its primitive. Without appearance the mesh has no materials and the writers write plain geometry.
// Textures: a textured appearance's material names a MeshTexture (one per image file, in order
// of first use, named after the file's stem as written in the grammar, its characters as for
// material names, made unique by "_2", "_3", ..., with the extension .png), and its primitive's
// triangles get UVs in the appearance's texture frame (geometry/texture_uv.hpp), on vertices of
// their own. Then the mesh has one UV per vertex (0 on untextured primitives); otherwise none,
// and its vertices are exactly as without textures.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "shape/kinds/paraboloid.hpp"  // kParaboloidRings
#include "shape/kinds/sphere.hpp"      // kSphereStacks
#include "shape/primitive.hpp"

namespace shapevo {

/// Appends the surface of `p` to `out` (its vertices after those already there).
/// `meshes` is Geometry::meshes; only Mesh primitives read it.
/// @throw std::out_of_range if a Mesh primitive names a mesh that `meshes` does not hold.
void appendSurface(const Primitive& p, const std::vector<MeshShape>* meshes, Mesh& out);

/// The surfaces of all primitives of a model, one after another, with their looks (above).
/// Material names are appearanceName(), made unique by a suffix "_2", "_3", ... in order of use.
/// @throw std::invalid_argument if geometry.appearance is neither empty nor one entry per
///        primitive; std::out_of_range if an appearance names a material that
///        geometry.materialNames does not hold (or a Mesh primitive a missing mesh, a texture
///        one that geometry.textures or geometry.textureFrames does not hold).
Mesh tessellate(const Geometry& geometry);

/// The name an appearance's material has in exported files (before tessellate() makes names
/// unique): its named material's name with every character other than A-Z a-z 0-9 _ - .
/// replaced by '_', or for the unnamed material 0 (and an empty name) "color_" followed by the
/// colour's 8-bit sRGB hex digits (mesh/mesh_material.hpp), e.g. "color_ff8800".
/// @throw std::out_of_range if `a.material` is not 0 and not an index into `materialNames`.
std::string appearanceName(const Appearance& a, const std::vector<std::string>* materialNames);

}  // namespace shapevo
