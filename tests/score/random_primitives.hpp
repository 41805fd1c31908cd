// Test helpers for the voxelizer tests of every primitive kind: random frames (rotations,
// mirrors, axis-aligned and grid-aligned placements), random primitives of a kind, two closed
// meshes (an octahedron and a non-convex L-shaped prism), a random fill/avoid target and the
// voxel-centre test of a box, round, roof or paraboloid primitive as one callable.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "genome/random.hpp"
#include "shape/primitive.hpp"
#include "shape/kinds.hpp"
#include "score/volume/volume_target.hpp"
#include "score/volume/voxelizer.hpp"

#include "../kind_params.hpp"

namespace shapevo::test {

/// Axes from a uniformly random rotation (a random unit quaternion).
inline glm::mat3 randomRotation(Rng& rng) {
    double q[4], n = 0;
    for (double& v : q) v = rng.normal(), n += v * v;
    n = std::sqrt(n);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                            {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                            {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
    glm::mat3 a;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) a[c][r] = float(m[c][r]);
    return a;
}

/// Axes that are a signed permutation of the grid axes (exact zeros and ones).
inline glm::mat3 randomAxisAligned(Rng& rng) {
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int* perm = perms[rng.below(6)];
    glm::mat3 a(0.0f);
    for (int c = 0; c < 3; ++c) a[c][perm[c]] = rng.below(2) ? 1.0f : -1.0f;
    return a;
}

/// Axes turned about one random grid axis (a building turned about the vertical): the turned
/// axes have an exact zero on the turning axis. The angle is a multiple of 90 degrees, within
/// 1e-5 of one (rows almost along a face), or uniform.
inline glm::mat3 randomTurnAboutGridAxis(Rng& rng) {
    const int axis = int(rng.below(3)), u = (axis + 1) % 3, v = (axis + 2) % 3;
    const std::uint32_t style = rng.below(3);
    const double quarter = 1.5707963267948966 * double(rng.below(4));
    const double angle = style == 0 ? quarter : style == 1 ? quarter + 1e-5 * (2 * rng.uniform() - 1) : 6.283185307179586 * rng.uniform();
    const float c = float(std::cos(angle)), s = float(std::sin(angle));
    glm::mat3 a(0.0f);
    a[axis][axis] = 1.0f;
    a[u][u] = c, a[u][v] = s;
    a[v][u] = -s, a[v][v] = c;
    return a;
}

/// A random primitive of `kind` around `grid`: styles 0-1 rotated, 2 axis-aligned, 3 axis-aligned
/// and grid-aligned (centre on a voxel centre or corner, half extents in half voxels, so surfaces
/// pass exactly through voxel centres); centres may leave the grid; one frame axis in four is
/// mirrored; sizes are sometimes thin (a thousandth of a voxel) or flat (zero). Cone tapers and
/// both roof fractions are 0, 1 or uniform in between. `gridAligned` forces style 3.
inline Primitive randomPrimitive(PrimitiveKind kind, const GridSpec& grid, Rng& rng, std::uint16_t meshes = 0,
                                 bool gridAligned = false) {
    Primitive p;
    p.kind = kind;
    const double n[3] = {double(grid.nx), double(grid.ny), double(grid.nz)};
    const int style = gridAligned ? 3 : int(rng.below(4));
    for (int j = 0; j < 3; ++j) {
        const double ext = n[j] * grid.voxelSize;
        if (style == 3) {
            p.centre[j] = float(grid.centre(j, long(rng.below(std::uint32_t(n[j])))) - (rng.below(2) ? 0.5 * grid.voxelSize : 0.0));
            p.half[j] = float(grid.voxelSize * 0.5 * double(1 + rng.below(12)));
        } else {
            p.centre[j] = float(grid.origin[j] - 0.3 * ext + 1.6 * ext * rng.uniform());
            p.half[j] = float(0.02 + 0.6 * rng.uniform());
        }
    }
    const std::uint32_t size = rng.below(40);
    if (size == 0) p.half[int(rng.below(3))] = float(grid.voxelSize * 1e-3);  // thin
    if (size == 1) p.half[int(rng.below(3))] = 0.0f;                         // flat
    if (style <= 1) p.axes = randomRotation(rng);
    else p.axes = randomAxisAligned(rng);
    if (rng.below(4) == 0) p.axes[int(rng.below(3))] *= -1.0f;  // a mirrored frame
    const std::uint32_t t = rng.below(4);
    const float taper = t == 0 ? 0.0f : t == 1 ? 1.0f : float(rng.uniform());
    std::uint16_t mesh = 0;
    float taperZ = 1.0f;
    if (kind == PrimitiveKind::Mesh) mesh = std::uint16_t(rng.below(meshes));
    if (kind == PrimitiveKind::Roof) {  // drawn last: the other kinds' draws stay as they were
        const std::uint32_t tz = rng.below(4);
        taperZ = tz == 0 ? 0.0f : tz == 1 ? 1.0f : float(rng.uniform());
    }
    setKindParams(p, taper, taperZ, mesh);
    return p;
}

/// The octahedron |u.x| + |u.y| + |u.z| <= 1, outward-facing.
inline MeshShape octahedron() {
    MeshShape m;
    m.path = "octahedron";
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::uint32_t sx = 0; sx < 2; ++sx)
        for (std::uint32_t sy = 0; sy < 2; ++sy)
            for (std::uint32_t sz = 0; sz < 2; ++sz) {
                std::array<std::uint32_t, 3> t{sx, 2 + sy, 4 + sz};
                if ((sx + sy + sz) % 2 == 1) std::swap(t[1], t[2]);  // counter-clockwise from outside
                m.triangles.push_back(t);
            }
    return m;
}

/// An L-shaped prism: the L {[-1,1]x[-1,0]} u {[-1,0]x[-1,1]} in x-y, extruded over z in [-1, 1].
inline MeshShape lPrism() {
    MeshShape m;
    m.path = "l-prism";
    const float l[6][2] = {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}};  // counter-clockwise
    for (int z = 0; z < 2; ++z)
        for (const auto& v : l) m.vertices.push_back({v[0], v[1], z ? 1.0f : -1.0f});
    const std::uint32_t fan[4][2] = {{4, 5}, {5, 0}, {0, 1}, {1, 2}};  // caps: fans around vertex 3
    for (const auto& f : fan) {
        m.triangles.push_back({6 + 3, 6 + f[0], 6 + f[1]});  // top, facing +z
        m.triangles.push_back({3, f[1], f[0]});              // bottom, facing -z
    }
    for (std::uint32_t i = 0; i < 6; ++i) {  // walls
        const std::uint32_t j = (i + 1) % 6;
        m.triangles.push_back({i, j, 6 + j});
        m.triangles.push_back({i, 6 + j, 6 + i});
    }
    return m;
}

inline VolumeTarget randomTarget(const GridSpec& grid, Rng& rng) {
    VolumeTarget t;
    t.grid = grid;
    t.fill.assign(grid.words(), 0);
    t.avoid.assign(grid.words(), 0);
    for (int z = 0; z < grid.nz; ++z)
        for (int y = 0; y < grid.ny; ++y)
            for (int x = 0; x < grid.nx; ++x) {
                const std::size_t w = (std::size_t(z) * grid.ny + y) * grid.wordsPerRow() + (x >> 6);
                const double u = rng.uniform();
                if (u < 0.3) t.fill[w] |= 1ULL << (x & 63), ++t.fillCount;
                else if (u < 0.4) t.avoid[w] |= 1ULL << (x & 63), ++t.avoidCount;
            }
    return t;
}

/// Brute-force counting: `hits` holds, per grid voxel (x fastest), how many primitives cover its
/// centre (capped at 2); add occupied, overlap, inside and avoided voxels to `c`, and set the
/// occupied voxels' bits in `bits` (sized grid.words()) if given.
inline void countHits(const std::vector<std::uint8_t>& hits, const VolumeTarget& t, VoxelCounts& c,
                      std::vector<std::uint64_t>* bits = nullptr) {
    const GridSpec& g = t.grid;
    for (int z = 0; z < g.nz; ++z)
        for (int y = 0; y < g.ny; ++y)
            for (int x = 0; x < g.nx; ++x) {
                const auto h = hits[(std::size_t(z) * g.ny + y) * g.nx + x];
                if (!h) continue;
                const std::size_t w = (std::size_t(z) * g.ny + y) * g.wordsPerRow() + (x >> 6);
                const std::uint64_t bit = 1ULL << (x & 63);
                if (bits) (*bits)[w] |= bit;
                ++c.occupied;
                if (h >= 2) ++c.overlap;
                if (t.fill[w] & bit) ++c.inside;
                if (t.avoid[w] & bit) ++c.avoided;
            }
}

using Local = std::array<long double, 3>;

/// Local coordinates u of world point w in long double, projected onto the frame's axes as
/// BoxFrame does (u_k = axis_k . (w - centre) / |half_k|).
inline Local localCoordinates(const Primitive& p, const double w[3]) {
    Local u;
    for (int k = 0; k < 3; ++k) {
        long double s = 0;
        for (int j = 0; j < 3; ++j) s += (long double)p.axes[k][j] * ((long double)w[j] - (long double)p.centre[j]);
        u[k] = s / std::fabs((long double)p.half[k]);
    }
    return u;
}

/// Signed "distance" of local point u from the surface of p (negative inside) in the textbook
/// form of shape/primitive.hpp, written independently of the kinds' code: every kind but Mesh.
inline long double textbookDistance(const Primitive& p, const Local& u) {
    const long double radial = std::sqrt(u[0] * u[0] + u[2] * u[2]);
    const long double slab = std::fabs(u[1]) - 1;
    auto clamped = [](float t) { return t >= 0 ? (long double)std::min(t, 1.0f) : 0.0L; };  // NaN -> 0
    switch (p.kind) {
    case PrimitiveKind::Box: return std::max({std::fabs(u[0]) - 1, slab, std::fabs(u[2]) - 1});
    case PrimitiveKind::Sphere: return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) - 1;
    case PrimitiveKind::Cylinder: return std::max(radial - 1, slab);
    case PrimitiveKind::Cone: {
        const long double t = taperOf(p);
        return std::max(radial - ((1 + t) / 2 + (t - 1) / 2 * u[1]), slab);
    }
    case PrimitiveKind::Roof: {
        const long double tx = clamped(taperOf(p)), tz = clamped(taperZOf(p));
        return std::max({std::fabs(u[0]) - ((1 + tx) / 2 + (tx - 1) / 2 * u[1]),
                         std::fabs(u[2]) - ((1 + tz) / 2 + (tz - 1) / 2 * u[1]), slab});
    }
    case PrimitiveKind::Paraboloid: return std::max(u[0] * u[0] + u[2] * u[2] - (1 - u[1]) / 2, slab);
    case PrimitiveKind::Mesh: break;
    }
    return NAN;
}

/// The inside test of a box, cylinder, cone, sphere, roof or paraboloid (the very functions the
/// voxelizer uses).
inline std::function<bool(double, double, double)> insideTest(const Primitive& p) {
    switch (p.kind) {
    case PrimitiveKind::Box: return [s = BoxFrame::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Cylinder: return [s = CylinderSolid::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Cone: return [s = ConeSolid::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Sphere: return [s = SphereSolid::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Roof: return [s = RoofSolid::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Paraboloid: return [s = ParaboloidSolid::from(p)](double x, double y, double z) { return s.contains(x, y, z); };
    case PrimitiveKind::Mesh: break;
    }
    return {};
}

}  // namespace shapevo::test
