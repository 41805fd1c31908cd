// Pieces: the scopes a split, repeat, comp, lot or copy statement makes of the current scope (the
// statement kinds are in grammar/grammar.hpp, PiecesKind; the rules are in grammars/README.md).
// Pure arithmetic on one scope; no allocation once `out` has grown.
//
// Flat scopes. A lot or a face is a scope whose size.z is 0: its x and y axes lie in it, its z
// axis is its outward normal. comp's faces (box axes X, Y, Z, size s):
//   top    centre +Y s.y/2, axes ( X, -Z,  Y), size (s.x, s.z, 0)
//   bottom centre -Y s.y/2, axes ( X,  Z, -Y), size (s.x, s.z, 0)
//   front  centre +Z s.z/2, axes ( X,  Y,  Z), size (s.x, s.y, 0)
//   back   centre -Z s.z/2, axes (-X,  Y, -Z), size (s.x, s.y, 0)
//   right  centre +X s.x/2, axes (-Z,  Y,  X), size (s.z, s.y, 0)
//   left   centre -X s.x/2, axes ( Z,  Y, -X), size (s.z, s.y, 0)
// (every face frame is right-handed when the box's is, and sees its face from outside with x to
// the right). Lots on a scope that is not flat lie in its ground plane: the plane through its
// origin spanned by X and -Z, facing +Y (so the start rule's lots lie on the world's y = 0).
// `extrude H` turns a flat scope into a volume standing on it: axes (x, z, -y), size
// (s.x, H, s.y), centre moved H/2 along the normal.
#pragma once
#include <cstdint>
#include <vector>

#include "grammar/grammar.hpp"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace shapevo {

/// A scope: the oriented frame statements act on (CGA style), centred on `origin`. `look`
/// indexes derive's appearances (0: the default; used only by grammars with colours).
struct Scope {
    glm::vec3 origin{0.0f};
    glm::mat3 axes{1.0f};
    glm::vec3 size{1.0f};
    std::uint32_t look = 0;
};

/// One piece: its scope and which Piece of the list runs on it.
struct PieceScope {
    Scope scope;
    std::uint32_t piece;
};

/// Most pieces one statement makes (a repeat of a tiny tile over a huge scope stops here).
inline constexpr std::uint32_t kMaxPieces = 4096;

/// The pieces `list` makes of `s` (appended to `out`, which is cleared first). Sizes and counts
/// are evaluated with `params` (the gene's frame) and the scope `s`.
void makePieces(const Grammar& g, const PieceList& list, const Scope& s, const float* params,
                const glm::vec3& parentSize, float* evalStack, std::vector<PieceScope>& out);

/// The scope `extrude height` makes of `s`.
Scope extrudeScope(const Scope& s, float height);

}  // namespace shapevo
