// Test helpers for the kinds' own parameters (Primitive::params, read and written through each
// kind's K::Params): tests draw generic numbers (a taper, a z taper, a mesh index) for primitives
// of any kind; these keep them as the primitive's kind does, and read them back (1 or 0 for a kind
// that has no such parameter).
#pragma once
#include <cstdint>

#include "shape/kinds.hpp"

namespace shapevo::test {

/// Cone: taper; Roof: taper and taperZ; Mesh: the mesh index; other kinds: no parameters.
inline void setKindParams(Primitive& p, float taper, float taperZ = 1.0f, std::uint16_t mesh = 0) {
    switch (p.kind) {
    case PrimitiveKind::Cone: setParams<ConeKind>(p, {taper}); break;
    case PrimitiveKind::Roof: setParams<RoofKind>(p, {taper, taperZ}); break;
    case PrimitiveKind::Mesh: setParams<MeshKind>(p, {mesh}); break;
    default: p.params = {}; break;
    }
}
/// A cone's or a roof's taper; 1 for other kinds.
inline float taperOf(const Primitive& p) {
    if (p.kind == PrimitiveKind::Cone) return paramsOf<ConeKind>(p).taper;
    if (p.kind == PrimitiveKind::Roof) return paramsOf<RoofKind>(p).taper;
    return 1.0f;
}
/// A roof's taperZ; 1 for other kinds.
inline float taperZOf(const Primitive& p) { return p.kind == PrimitiveKind::Roof ? paramsOf<RoofKind>(p).taperZ : 1.0f; }
/// A mesh primitive's mesh index; 0 for other kinds.
inline std::uint16_t meshIndexOf(const Primitive& p) { return p.kind == PrimitiveKind::Mesh ? paramsOf<MeshKind>(p).mesh : 0; }

}  // namespace shapevo::test
