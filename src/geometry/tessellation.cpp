// Tessellation: each primitive's kind builds its surface (K::surface, static dispatch).
#include "geometry/tessellation.hpp"

#include "shape/kinds.hpp"
#include "shape/surface.hpp"

namespace shapevo {

void appendSurface(const Primitive& p, const std::vector<MeshShape>* meshes, Mesh& out) {
    SurfaceBuilder s(p, out);
    visitKind(p.kind, [&](auto kind) { decltype(kind)::type::surface(s, p, meshes); });
}

Mesh tessellate(const Geometry& geometry) {
    Mesh m;
    for (const Primitive& p : geometry.primitives) appendSurface(p, geometry.meshes, m);
    return m;
}

}  // namespace shapevo
