// textureLook: what derive does at a `texture` statement (grammar/grammar.hpp,
// StatementKind::Texture). The new appearance is white with the texture's material and image,
// and it fixes a texture frame (shape/texture.hpp) from the scope at the statement: its centre
// and axes, and the tile lengths |size.x| / SX, |size.y| / SY, |size.z| / SX (the x length where
// size.z is 0), so that every primitive below, however later statements cut and move its scope,
// measures its UV coordinates in the same world-scale frame (geometry/texture_uv.hpp).
// Allocates nothing once `looks` and `frames` have grown.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/pieces.hpp"
#include "grammar/grammar.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

/// The tile lengths of a texture frame over a scope of `size` stretched by (sx, sy).
glm::vec3 textureTile(const glm::vec3& size, float sx, float sy);

/// The appearance statement `st` (a Texture) makes in scope `s`: appended to `looks` (its frame to
/// `frames`); returns its index in `looks`.
std::uint32_t textureLook(const Grammar& g, const Statement& st, std::vector<Appearance>& looks, const Scope& s,
                          const float* params, const glm::vec3& parentSize, float* evalStack,
                          std::vector<TextureFrame>& frames);

}  // namespace shapevo
