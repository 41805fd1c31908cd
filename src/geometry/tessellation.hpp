// Tessellation: the surface of a primitive as outward-facing triangles in world coordinates, for
// exported meshes (OBJ, PLY, GLB). Each kind is built in the frame's unit coordinates u (see
// primitive.hpp) and placed with world = centre + axes * (half * u); frames with det(axes) < 0
// (mirrored) get their triangles reversed so that they still face outwards.
//   Box       8 vertices, 12 triangles
//   Cylinder  a kRoundSides-gon prism: 2 * kRoundSides vertices, 4 * kRoundSides - 4 triangles
//   Cone      a kRoundSides-gon frustum like the cylinder; with taper 0 a pyramid with one apex
//             vertex: kRoundSides + 1 vertices, 2 * kRoundSides - 2 triangles
//   Sphere    a UV sphere of kRoundSides slices and kSphereStacks stacks (poles on the y axis)
//   Mesh      the grammar's mesh Geometry::meshes[mesh], vertex for vertex
// Every piece is closed: each edge is shared by exactly two triangles, in opposite directions.
#pragma once
#include <vector>

#include "geometry/primitive.hpp"
#include "mesh/mesh.hpp"

namespace shapevo {

/// Latitude bands of the UV sphere (kRoundSides meridians); vertex rings at latitudes
/// -90 + 180 * i / kSphereStacks degrees, i = 1 .. kSphereStacks - 1, plus the two poles.
inline constexpr int kSphereStacks = 8;

/// Appends the surface of `p` to `out` (its vertices after those already there).
/// `meshes` is Geometry::meshes; only Mesh primitives read it.
/// @throw std::out_of_range if a Mesh primitive names a mesh that `meshes` does not hold.
void appendSurface(const Primitive& p, const std::vector<MeshShape>* meshes, Mesh& out);

/// The surfaces of all primitives of a model, one after another.
Mesh tessellate(const Geometry& geometry);

}  // namespace shapevo
