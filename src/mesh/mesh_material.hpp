// Mesh materials: what the mesh writers (OBJ, PLY, GLB) share about a mesh's colours. Colours are
// linear RGB in [0, 1] everywhere inside shapevo; files that want 8-bit colour (PLY vertex
// colours, the hex digits of generated material names) get the sRGB encoding of IEC 61966-2-1:
//   s = 12.92 * c                      for c <= 0.0031308
//   s = 1.055 * c^(1 / 2.4) - 0.055    otherwise,       byte = round(255 * s)
// so linear 0.5 is byte 188 (0xbc) and 0.8 byte 231 (0xe7). checkMaterials() states and
// checks what a mesh with materials promises its writers.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace shapevo {

/// `c` limited to [0, 1]; NaN and -0 become +0.
float clampUnit(float c);
/// The sRGB encoding of linear channel `c` (clamped first), in [0, 1].
float linearToSrgb(float c);
/// The 8-bit sRGB bytes of a linear colour: round(255 * linearToSrgb(channel)).
std::array<std::uint8_t, 3> srgbBytes(const glm::vec3& linear);
/// srgbBytes as six lowercase hex digits ("ff8800").
std::string srgbHex(const glm::vec3& linear);

/// True if `name` can name a material in every format: non-empty, only A-Z a-z 0-9 _ - .
bool isMaterialName(std::string_view name);

/// Checks that `mesh` either has no materials, no triangleMaterials, no textures and no UVs, or:
/// one material index per triangle, each naming a material; names as isMaterialName() and
/// pairwise different; colours finite and in [0, 1]; each material's texture -1 or one of
/// Mesh::textures, whose file names are as isMaterialName(), end in .png and are pairwise
/// different and whose bytes start like a PNG; one finite UV per vertex if a material has a
/// texture and none otherwise. @throw InputError naming `path` otherwise.
void checkMaterials(const Mesh& mesh, const std::string& path);

/// The triangles of each material in mesh order: result[m] lists the indices of the triangles
/// of material m. A mesh without materials gives one list of all its triangles.
std::vector<std::vector<std::uint32_t>> trianglesByMaterial(const Mesh& mesh);

}  // namespace shapevo
