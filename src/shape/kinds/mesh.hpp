// The Mesh kind: `mesh "FILE"` in a grammar (a closed OBJ/PLY/STL mesh, read once when the grammar
// is loaded into Grammar::meshes; the primitive refers to it by index). Solid: the closed mesh,
// whose vertices are in the frame's unit coordinates. Voxel rows: MeshSolid below, a Mesh
// primitive placed in world space, its voxel-centre inside test and the crossings of voxel rows
// with its triangles. Silhouette: one piece per triangle (all triangles, front or back).
// Surface: the mesh, vertex for vertex. A primitive whose mesh is missing draws nothing (the
// surface throws std::out_of_range).
//
// The inside test (the definition): a ray from the voxel centre along +x; the centre is inside
// iff the ray crosses an odd number of triangles. A row (fixed y, z) crosses a triangle iff the
// point (y, z) lies in the triangle's projection onto the y-z plane, decided by these rules:
//  - which side of an edge the point lies on is computed from the edge's two end points in a
//    canonical order (by (y, z)), so the two triangles that share an edge always put the point on
//    opposite sides of it, even with rounding;
//  - an exact hit on an edge or a vertex is broken by symbolic perturbation: the point is moved
//    to (y + e, z + e^2) for an infinitesimal e > 0, so a point on an edge belongs to exactly one
//    side (half-open edges) and a triangle seen edge-on (zero projected area) is never crossed;
//  - the point must lie in the half-open bounding box [y_min, y_max) x [z_min, z_max) of the
//    triangle's projection (the same perturbation), which also makes every crossing local.
// The crossing's x is the barycentric interpolation of the triangle's x coordinates (it always
// lies between them); a crossing at exactly the voxel centre is not "ahead" of it (counted if
// x_cross > x), so each run of covered voxels is half-open: [x_cross_0, x_cross_1).
//
// Per row the crossings are computed once, sorted, and the runs where the number of crossings
// ahead is odd are filled (rowRuns): the same voxels as the test, without testing each one.
// With exact arithmetic every row crosses a closed mesh an even number of times (the rules never
// let both triangles at an edge or around a vertex claim the point, nor none), so the runs are
// the pairs [c_0, c_1), [c_2, c_3), ... In doubles the side tests are consistent per edge, but a
// row passing within rounding of a projected vertex could still see an odd count; the definition
// then puts everything before its first crossing inside, and rowRuns follows it (up to the
// halo), so the rows stay exact even then. (The tests find no odd row, vertices on rows included.)
//
// Vertices are placed by the forward map c + sum_k axis_k * h_k * u_k; the other kinds project
// onto the axes instead. The two agree for orthonormal axes, i.e. to ~1e-7 for float frames.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_shape.hpp"
#include "shape/box_frame.hpp"
#include "shape/chord_rows.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// One crossing of a row with a triangle: row key and x.
struct RowCrossing {
    std::uint32_t row;
    double x;
    bool operator<(const RowCrossing& o) const { return row < o.row || (row == o.row && x < o.x); }
};

class MeshSolid {
public:
    using Vertex = std::array<double, 3>;

    /// Place `shape` in `p`'s frame: world = c + sum_k axis_k * (|half_k| * u_k), in double.
    /// Reuses the vertex buffer. False (covers nothing) for a non-finite frame or a zero half
    /// extent (a flat mesh has no volume).
    bool place(const Primitive& p, const MeshShape& shape) {
        shape_ = &shape;
        placed_ = false;
        const BoxFrame b = BoxFrame::from(p);
        if (!b.finite()) return false;
        for (int k = 0; k < 3; ++k)
            if (!(b.h[k] > 0.0)) return false;
        world_.resize(shape.vertices.size());
        for (int j = 0; j < 3; ++j) lo_[j] = INFINITY, hi_[j] = -INFINITY;
        for (std::size_t v = 0; v < shape.vertices.size(); ++v) {
            const glm::vec3& u = shape.vertices[v];
            for (int j = 0; j < 3; ++j) {
                const double w = b.c[j] + b.a[0][j] * (b.h[0] * double(u[0])) + b.a[1][j] * (b.h[1] * double(u[1])) +
                                 b.a[2][j] * (b.h[2] * double(u[2]));
                world_[v][j] = w;
                lo_[j] = std::min(lo_[j], w);
                hi_[j] = std::max(hi_[j], w);
            }
        }
        for (int j = 0; j < 3; ++j)
            if (!std::isfinite(lo_[j]) || !std::isfinite(hi_[j])) return false;
        placed_ = !shape.triangles.empty();
        return placed_;
    }
    double lo(int j) const { return lo_[j]; }
    double hi(int j) const { return hi_[j]; }
    std::size_t triangles() const { return placed_ ? shape_->triangles.size() : 0; }

    /// Does row (y, z) cross triangle t, and where? (The crossing rule described above.)
    bool crossing(std::size_t t, double y, double z, double& x) const {
        const Corners c = corners(t);
        return c.inBox(y, z) && crossingInBox(c, y, z, x);
    }

    /// The voxel-centre test: does the +x ray from (x, y, z) cross an odd number of triangles?
    /// (Never, if the last place() failed.)
    bool contains(double x, double y, double z) const {
        bool inside = false;
        double xc;
        for (std::size_t t = 0; t < triangles(); ++t)
            if (crossing(t, y, z, xc) && xc > x) inside = !inside;
        return inside;
    }

    /// Append the crossings of rows y in [y0, y1], z in [z0, z1] (grid indices) to `out`, with
    /// row key (z - z0) * (y1 - y0 + 1) + (y - y0): crossing() on the rows near each triangle's
    /// bounding box, so the work is proportional to the rows the surface covers.
    void collectCrossings(const GridSpec& grid, long y0, long y1, long z0, long z1, std::vector<RowCrossing>& out) const {
        const std::uint32_t ny = std::uint32_t(y1 - y0 + 1);
        const double perUnit = 1.0 / grid.voxelSize;
        // Rows whose centre may lie in [vmin, vmax): a superset by kSlack index units (rounding
        // is ~1e-13 of them), so that crossing()'s exact test is the only one that decides.
        constexpr double kSlack = 1e-3;
        auto rows = [&](int axis, long first, long last, double vmin, double vmax, long& a, long& b) {
            const double base = -grid.origin[axis] * perUnit - 0.5;  // index of a centre at v: base + v / voxel
            const double ta = std::max(std::ceil(base + vmin * perUnit - kSlack), double(first));
            const double tb = std::min(std::ceil(base + vmax * perUnit + kSlack) - 1.0, double(last));
            if (!(ta <= tb)) return false;
            a = long(ta);
            b = long(tb);
            return true;
        };
        for (std::size_t t = 0; t < triangles(); ++t) {
            const Corners c = corners(t);
            long ya, yb, za, zb;
            if (!rows(1, y0, y1, c.ymin, c.ymax, ya, yb) || !rows(2, z0, z1, c.zmin, c.zmax, za, zb)) continue;
            for (long z = za; z <= zb; ++z) {
                const double cz = grid.centre(2, z);
                for (long y = ya; y <= yb; ++y) {
                    const double cy = grid.centre(1, y);
                    double x;
                    if (c.inBox(cy, cz) && crossingInBox(c, cy, cz, x))
                        out.push_back({std::uint32_t(z - z0) * ny + std::uint32_t(y - y0), x});
                }
            }
        }
    }

private:
    /// A triangle's world corners and the half-open bounding box of its y-z projection.
    struct Corners {
        const Vertex *v0, *v1, *v2;
        double ymin, ymax, zmin, zmax;
        bool inBox(double y, double z) const { return y >= ymin && y < ymax && z >= zmin && z < zmax; }
    };
    Corners corners(std::size_t t) const {
        const auto& tri = shape_->triangles[t];
        const Vertex &v0 = world_[tri[0]], &v1 = world_[tri[1]], &v2 = world_[tri[2]];
        return {&v0, &v1, &v2, std::min({v0[1], v1[1], v2[1]}), std::max({v0[1], v1[1], v2[1]}),
                std::min({v0[2], v1[2], v2[2]}), std::max({v0[2], v1[2], v2[2]})};
    }
    /// The rest of the crossing rule, for a point in the triangle's box.
    static bool crossingInBox(const Corners& c, double y, double z, double& x) {
        double e0, e1, e2;  // edge functions; e_i belongs to the edge opposite vertex i
        const int s0 = edgeSide(*c.v1, *c.v2, y, z, e0);
        const int s1 = edgeSide(*c.v2, *c.v0, y, z, e1);
        if (s1 != s0) return false;
        const int s2 = edgeSide(*c.v0, *c.v1, y, z, e2);
        if (s2 != s0) return false;
        const double sum = e0 + e1 + e2;
        x = sum != 0.0 ? (e0 * (*c.v0)[0] + e1 * (*c.v1)[0] + e2 * (*c.v2)[0]) / sum : (*c.v0)[0];
        return true;
    }
    /// Side of the directed edge a -> b that point (y, z) lies on in the y-z plane (+1 left,
    /// -1 right) and the edge function e (twice the signed area of a, b, point).
    static int edgeSide(const Vertex& a, const Vertex& b, double y, double z, double& e) {
        const bool flip = b[1] < a[1] || (b[1] == a[1] && b[2] < a[2]);
        const Vertex& p = flip ? b : a;
        const Vertex& q = flip ? a : b;
        const double dy = q[1] - p[1], dz = q[2] - p[2];
        e = dy * (z - p[2]) - dz * (y - p[1]);
        // exact hit: the sign at (y + eps, z + eps^2) is that of -dz * eps + dy * eps^2
        int s = e > 0.0 ? 1 : e < 0.0 ? -1 : (dz != 0.0 ? (dz > 0.0 ? -1 : 1) : (dy > 0.0 ? 1 : -1));
        if (flip) s = -s, e = -e;
        return s;
    }

    const MeshShape* shape_ = nullptr;
    bool placed_ = false;
    std::vector<Vertex> world_;
    double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
};

/// The covered runs of one row from its sorted crossings c_0 <= ... <= c_{n-1}: voxel centres x
/// with an odd number of crossings ahead (c > x), i.e. [c_{m-1}, c_m) for m = n-1, n-3, ...
/// (and x < c_0 when n is odd, which a closed mesh never gives). Calls run(lo, hi) with the
/// index interval of each non-empty run within [first, last].
template <class Run>
[[gnu::always_inline]] inline void rowRuns(const RowCrossing* c, std::size_t n, const GridSpec& grid, long first, long last, Run run) {
    const double base = -grid.origin[0] / grid.voxelSize - 0.5, perUnit = 1.0 / grid.voxelSize;
    for (long m = long(n) - 1; m >= 0; m -= 2) {
        const double from = m >= 1 ? c[m - 1].x : -INFINITY, to = c[m].x;
        const long lo = firstTrue(first, last, base + from * perUnit, [&](long i) { return grid.centre(0, i) >= from; });
        const long hi = firstTrue(first, last, base + to * perUnit, [&](long i) { return grid.centre(0, i) >= to; }) - 1;
        if (lo <= hi) run(lo, hi);
    }
}

struct MeshKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Mesh;
    static constexpr std::string_view keyword = "mesh";
    /// Its own parameters (Primitive::params): the index of its mesh in Geometry::meshes.
    struct Params {
        std::uint16_t mesh = 0;
    };
    /// Grammar: a file name in quotes; the statement's slot is its index in Grammar::meshes.
    template <class Args>
    static void parseArguments(Args& a) {
        a.meshFile();
    }
    template <class Args>
    static void emit(Primitive& p, const Args& a) {
        setParams<MeshKind>(p, {a.slot()});
    }
    /// The primitive's mesh, or null if `meshes` does not hold it.
    static const MeshShape* shapeOf(const Primitive& p, const std::vector<MeshShape>* meshes) {
        const std::uint16_t mesh = paramsOf<MeshKind>(p).mesh;
        return meshes && mesh < meshes->size() ? &(*meshes)[mesh] : nullptr;
    }

    /// The voxelizer's reusable work space for meshes (no allocation once warm).
    struct VoxelScratch {
        MeshSolid mesh;                       ///< the mesh being voxelized (its vertex buffer is reused)
        std::vector<RowCrossing> crossings;   ///< its row crossings (reused), in triangle order
        std::vector<RowCrossing> byRow;       ///< the same, bucketed by row
        std::vector<std::uint32_t> rowEnd;    ///< per row: end of its bucket in byRow
    };
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>* meshes, Rows& rows, Counts& counts) {
        const MeshShape* shape = shapeOf(p, meshes);
        if (!shape) return;
        VoxelScratch& v = rows.template scratch<MeshKind>();
        const GridSpec& grid = rows.grid();
        if (!v.mesh.place(p, *shape)) return;
        double c[3], reach[3];
        for (int j = 0; j < 3; ++j) {
            c[j] = 0.5 * (v.mesh.lo(j) + v.mesh.hi(j));
            reach[j] = 0.5 * (v.mesh.hi(j) - v.mesh.lo(j));
        }
        long first[3], last[3];
        if (!rows.indexBounds(c, reach, first, last)) return;
        counts.rows += std::uint64_t(last[1] - first[1] + 1) * std::uint64_t(last[2] - first[2] + 1);
        v.crossings.clear();
        v.mesh.collectCrossings(grid, first[1], last[1], first[2], last[2], v.crossings);
        // Bucket the crossings by row (a counting sort: the row keys are dense), then sort each
        // row's few crossings by x.
        const std::uint32_t ny = std::uint32_t(last[1] - first[1] + 1);
        const std::size_t rowCount = std::size_t(ny) * std::size_t(last[2] - first[2] + 1);
        v.rowEnd.assign(rowCount + 1, 0);
        for (const RowCrossing& x : v.crossings) ++v.rowEnd[x.row + 1];
        for (std::size_t r = 0; r < rowCount; ++r) v.rowEnd[r + 1] += v.rowEnd[r];  // now: where row r starts
        v.byRow.resize(v.crossings.size());
        for (const RowCrossing& x : v.crossings) v.byRow[v.rowEnd[x.row]++] = x;  // afterwards: where row r ends
        // Runs may start before a row's first crossing only if it crosses an odd number of
        // triangles (never for a closed mesh); the whole halo keeps even that case exact.
        const long xFirst = -long(grid.nx), xLast = 2 * long(grid.nx) - 1;
        for (std::uint32_t r = 0, begin = 0; r < rowCount; begin = v.rowEnd[r], ++r) {
            const std::uint32_t end = v.rowEnd[r];
            if (begin == end) continue;
            RowCrossing* x = v.byRow.data() + begin;
            std::sort(x, x + (end - begin));
            const long y = first[1] + long(r % ny), z = first[2] + long(r / ny);
            rowRuns(x, end - begin, grid, xFirst, xLast, [&](long lo, long hi) { rows.addRow(y, z, lo, hi, counts); });
        }
    }

    /// One piece per triangle: snapped once per vertex on the fast path; a triangle with a vertex
    /// behind the clip plane or beyond the guard band is cut and clipped on its own.
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive& p, Outline& out) {
        using Homogeneous = typename Builder::Homogeneous;
        const MeshShape& mesh = *shapeOf(p, b.preparedMeshes());  // prepare() checked it
        auto& h = b.homogeneousScratch();
        auto& snapped = b.snappedScratch();
        auto& fast = b.fastScratch();
        const std::size_t n = mesh.vertices.size();
        h.resize(n);
        snapped.resize(n);
        fast.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec3& v = mesh.vertices[i];
            h[i] = map.apply(glm::dvec3(v.x, v.y, v.z));
            const double x = h[i].x / h[i].w, y = h[i].y / h[i].w;
            fast[i] = h[i].clip >= 0.0 && b.insideGuard(x, y);
            if (fast[i]) snapped[i] = snapToFixed(x, y);
        }
        Homogeneous polygon[4];
        for (const auto& tri : mesh.triangles) {
            if (tri[0] >= n || tri[1] >= n || tri[2] >= n) continue;
            if (fast[tri[0]] && fast[tri[1]] && fast[tri[2]]) {
                const auto first = std::uint32_t(out.points.size());
                for (int k = 0; k < 3; ++k) out.points.push_back(snapped[tri[k]]);
                out.pieces.push_back({first, 3, 1, 3});
                continue;
            }
            // Cut the triangle by the clip plane (Sutherland-Hodgman keeps its cyclic order).
            std::size_t m = 0;
            for (int k = 0; k < 3; ++k) {
                const Homogeneous &a = h[tri[k]], &c = h[tri[(k + 1) % 3]];
                if (a.clip >= 0.0) polygon[m++] = a;
                if ((a.clip >= 0.0) != (c.clip >= 0.0)) {
                    const double t = a.clip / (a.clip - c.clip);
                    polygon[m++] = {a.x + (c.x - a.x) * t, a.y + (c.y - a.y) * t, a.w + (c.w - a.w) * t, 0.0};
                }
            }
            b.addClippedPiece(polygon, m, true, out);
        }
    }

    /// @throw std::out_of_range if `meshes` does not hold the primitive's mesh.
    static void surface(SurfaceBuilder& s, const Primitive& p, const std::vector<MeshShape>* meshes) {
        const std::uint16_t mesh = paramsOf<MeshKind>(p).mesh;
        if (!meshes || mesh >= meshes->size())
            throw std::out_of_range("mesh primitive refers to mesh " + std::to_string(mesh) + " but the model has " +
                                    std::to_string(meshes ? meshes->size() : 0));
        const MeshShape& m = (*meshes)[mesh];
        for (const glm::vec3& v : m.vertices) s.vertex(v);
        for (const auto& t : m.triangles) s.triangle(t[0], t[1], t[2]);
    }
};

}  // namespace shapevo
