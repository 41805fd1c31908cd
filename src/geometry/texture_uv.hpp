// Texture UVs: the UV coordinates of a textured primitive's triangles, measured in world units in
// the texture frame of its `texture` statement (shape/texture.hpp: origin o, unit axes ax, ay,
// az, tile lengths tile_x, tile_y, tile_z), so that pieces cut from a textured scope by later
// splits, repeats, comps and lots keep the tile size of the whole and the image continues across
// piece boundaries (CastleMaker's auto-correction, papers/castlemaker-crl.txt §6.1), and the
// stretch factors SX, SY scale it. One unit of u or v is one whole image; OBJ's convention
// (v = 0 is the image's bottom row; the GLB writer flips v for glTF).
//
// Per triangle, with n its (outward) normal and, for each vertex p, d = p - o, the frame axis a
// with the largest |n . a| decides (ties: az, then ax, then ay):
//   az: u =  sign(n . az) (d . ax) / tile_x,   v = (d . ay) / tile_y
//   ax: u = -sign(n . ax) (d . az) / tile_z,   v = (d . ay) / tile_y
//   ay: u = (d . ax) / tile_x,                 v = -sign(n . ay) (d . az) / tile_z
// (sign(0) = +1), so a face reads left to right seen from outside, on the back and the left too.
// Round kinds (those with a K::textureRadius: cylinder, cone, paraboloid; their axis is the primitive's y axis w, turned so
// that w . ay >= 0): a triangle whose |n . w| is below sqrt(1/2) (their sides) is mapped
// cylindrically instead:
//   u = phi R / tile_x,   v = (d . w) / tile_y
// where phi is the vertex's angle about w (right-handed, from the primitive's x axis, so u grows
// to the right seen from outside) and R the primitive's mean radius in world units (its kind's
// textureRadius): (half.x + half.z) / 2 for a cylinder, times (1 + taper) / 2 for a cone, times 2/3 for a paraboloid (its
// radius averaged over its height). Each triangle's angles are unwrapped around the angle of its
// centroid, so no triangle straddles the seam (at the primitive's -x side, where u jumps by
// 2 pi R / tile_x); a vertex on the axis (a cone's apex) takes the mean angle of the others.
// Caps (|n . w| >= sqrt(1/2)) use the planar rule above. Where w = ay (a round primitive
// standing in its frame, the usual case) v is the planar rule's v.
// A tile length that is not a finite positive number makes that term 0.
//
// The triangles of the primitive get their own vertices: a vertex used by two triangles with
// different UVs (box corners, seam vertices) is duplicated, one with equal UVs stays shared.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>

#include "mesh/mesh.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// The UV coordinates of world point `p` on a triangle of normal `n` by the planar rule above.
glm::vec2 planarUv(const TextureFrame& frame, const glm::vec3& n, const glm::vec3& p);

/// Gives the surface of primitive `p` — the vertices [firstVertex, end) and triangles
/// [firstTriangle, end) of `mesh`, as appendSurface() made them — UV coordinates in `frame`, as
/// above. `mesh.uvs` must hold exactly firstVertex entries; afterwards it holds one per vertex.
/// The primitive's vertices are rebuilt (duplicated where their UVs differ, in order of first use).
void applyTextureUv(const Primitive& p, const TextureFrame& frame, std::uint32_t firstVertex, std::size_t firstTriangle,
                    Mesh& mesh);

}  // namespace shapevo
