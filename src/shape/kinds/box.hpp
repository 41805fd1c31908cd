// The Box kind: `box` in a grammar (no arguments). Solid |u.x| <= 1, |u.y| <= 1, |u.z| <= 1 in
// the frame's unit coordinates: BoxFrame (shape/box_frame.hpp) is its exact voxel-centre test.
// Voxel rows: per row the intersection of three slabs' exact index intervals (the slabs that do
// not vary with y once per z slice; neighbouring rows alike go in as one run; a box turned about
// x or y only is one y range per z slice); a box whose axes are grid axes is one box of index
// ranges (no per-row work). Silhouette: its 8 corners, of which
// the fast path keeps the silhouette vertices. Surface: 8 vertices, 12 triangles.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

#include "shape/box_frame.hpp"
#include "shape/outline.hpp"
#include "shape/surface.hpp"

namespace shapevo {

/// True if every box axis is a distinct grid axis (the common case: unrotated grammars, mirrors).
inline bool axisAligned(const BoxFrame& b) {
    int seen = 0;
    for (int k = 0; k < 3; ++k) {
        int nonzero = 0, axis = 0;
        for (int j = 0; j < 3; ++j)
            if (b.a[k][j] != 0.0) ++nonzero, axis = j;
        if (nonzero != 1 || (seen & (1 << axis))) return false;
        seen |= 1 << axis;
    }
    return true;
}

struct BoxKind {
    static constexpr PrimitiveKind kind = PrimitiveKind::Box;
    static constexpr std::string_view keyword = "box";
    /// Grammar: nothing follows the keyword.
    template <class Args>
    static void parseArguments(Args&) {}
    /// Derivation: nothing beyond the frame.
    template <class Args>
    static void emit(Primitive&, const Args&) {}

    /// Voxel rows of `p` (the kinds' row interface: see voxelizeChords in shape/chord_rows.hpp).
    template <class Rows, class Counts>
    static void voxelize(const Primitive& p, const std::vector<MeshShape>*, Rows& rows, Counts& counts) {
        const BoxFrame b = BoxFrame::from(p);
        if (!b.finite()) return;
        const GridSpec& grid = rows.grid();
        const long n[3] = {grid.nx, grid.ny, grid.nz};
        const double reach[3] = {b.reach(0), b.reach(1), b.reach(2)};
        long first[3], last[3];
        if (!rows.indexBounds(b.c, reach, first, last)) return;
        if (axisAligned(b)) {
            // Each slab depends on one grid axis only (the other products are exact zeros, and
            // v + 0 == v), so the covered voxels are a box of index ranges, one per axis.
            long range[3][2];
            for (int k = 0; k < 3; ++k) {
                int j = 0;
                while (b.a[k][j] == 0.0) ++j;
                if (!slabInterval(SlabLine::of(b, k, j, grid), 0.0, grid, first[j], last[j], range[j][0], range[j][1])) return;
            }
            // Everything below is arithmetic on the three ranges: rows off the grid in y or z count
            // their whole interval as outside, rows on it count the part beyond x.
            const long lo = range[0][0], hi = range[0][1];
            const std::uint64_t len = std::uint64_t(hi - lo + 1);
            const std::uint64_t rowsY = std::uint64_t(range[1][1] - range[1][0] + 1);
            const std::uint64_t rowsZ = std::uint64_t(range[2][1] - range[2][0] + 1);
            counts.rows += rowsY * rowsZ;
            const long gy0 = std::max(range[1][0], 0L), gy1 = std::min(range[1][1], n[1] - 1);
            const long gz0 = std::max(range[2][0], 0L), gz1 = std::min(range[2][1], n[2] - 1);
            const long gx0 = std::max(lo, 0L), gx1 = std::min(hi, n[0] - 1);
            const std::uint64_t inGridRows =
                (gy0 <= gy1 && gz0 <= gz1) ? std::uint64_t(gy1 - gy0 + 1) * std::uint64_t(gz1 - gz0 + 1) : 0;
            const std::uint64_t inGridLen = gx0 <= gx1 ? std::uint64_t(gx1 - gx0 + 1) : 0;
            counts.outside += (rowsY * rowsZ - inGridRows) * len + inGridRows * (len - inGridLen);
            if (inGridRows == 0 || inGridLen == 0) return;
            for (long z = gz0; z <= gz1; ++z) rows.markRows(z, gy0, gy1, gx0, gx1);
            return;
        }
        // A slab whose axis has no y (or z) component gives every row of a z (or y) the same
        // term: the product is an exact zero, and adding a zero changes no value (at most the sign
        // of a zero, which no test below can see). So the slabs without y are intersected once per
        // z, and only the others row by row: a box turned about the vertical axis, as every
        // building is, costs one cheap test per row instead of three intervals.
        const SlabLine slab[3] = {SlabLine::of(b, 0, 0, grid), SlabLine::of(b, 1, 0, grid), SlabLine::of(b, 2, 0, grid)};
        int perZ[3], perRow[3], nPerZ = 0, nPerRow = 0;
        for (int k = 0; k < 3; ++k) (b.a[k][1] == 0.0 ? perZ[nPerZ++] : perRow[nPerRow++]) = k;
        // If the other slabs have no x component either (a box turned about x or y only), a row
        // passes or fails them whole, and the passing rows of a z are one range of y: the same
        // test, |a.y * (y - c.y) + a.z * (z - c.z)| <= h, read along the y axis.
        bool wholeRows = true;
        for (int i = 0; i < nPerRow; ++i) wholeRows = wholeRows && b.a[perRow[i]][0] == 0.0;
        SlabLine alongY[3];
        if (wholeRows)
            for (int i = 0; i < nPerRow; ++i) alongY[i] = SlabLine::of(b, perRow[i], 1, grid);
        const double anyY = grid.centre(1, first[1]);
        const std::uint64_t rowsPerZ = std::uint64_t(last[1] - first[1] + 1);
        for (long z = first[2]; z <= last[2]; ++z) {
            const double cz = grid.centre(2, z);
            long zlo = first[0], zhi = last[0];
            bool any = true;
            for (int i = 0; i < nPerZ && any; ++i) {
                const int k = perZ[i];
                any = slabInterval(slab[k], b.rowTerm(k, anyY, cz), grid, zlo, zhi, zlo, zhi);
            }
            if (!any) {
                counts.rows += rowsPerZ;
                continue;
            }
            if (wholeRows) {
                counts.rows += rowsPerZ;
                long ylo = first[1], yhi = last[1];
                bool rowsPass = true;
                for (int i = 0; i < nPerRow && rowsPass; ++i) {
                    const int k = perRow[i];
                    rowsPass = slabInterval(alongY[i], b.a[k][2] * (cz - b.c[2]), grid, ylo, yhi, ylo, yhi);
                }
                if (rowsPass) rows.addRows(ylo, yhi, z, zlo, zhi, counts);
                continue;
            }
            // Neighbouring rows with the same interval go in as one run (all of a z's rows, for a
            // building): fewer, longer runs to write and, when recording, to keep.
            long runY0 = 0, runY1 = -1, runLo = 0, runHi = -1;
            for (long y = first[1]; y <= last[1]; ++y) {
                ++counts.rows;
                const double cy = grid.centre(1, y);
                long lo = zlo, hi = zhi;
                bool row = true;
                for (int i = 0; i < nPerRow && row; ++i) {
                    const int k = perRow[i];
                    row = slabInterval(slab[k], b.rowTerm(k, cy, cz), grid, lo, hi, lo, hi);
                }
                if (row && runY1 == y - 1 && lo == runLo && hi == runHi) {
                    runY1 = y;
                    continue;
                }
                if (runY1 >= runY0) rows.addRows(runY0, runY1, z, runLo, runHi, counts);
                runY0 = y, runY1 = row ? y : y - 1, runLo = lo, runHi = hi;
            }
            if (runY1 >= runY0) rows.addRows(runY0, runY1, z, runLo, runHi, counts);
        }
    }

    /// Silhouette pieces (score/image/silhouette_outline.hpp): the square two-ring fast path, else all
    /// 8 corners as one convex piece.
    template <class Builder>
    static void outline(Builder& b, const typename Builder::LocalMap& map, const Primitive&, Outline& out) {
        if (!b.addRingsFast(map, &b.squareRing(), 1.0, out)) b.addConvex(map, b.boxShape(), out);
    }

    /// Surface: corners indexed by bits (x, y, z) = (i & 1, i >> 1 & 1, i >> 2 & 1); quads -x, +x,
    /// -y, +y, -z, +z.
    static void surface(SurfaceBuilder& s, const Primitive&, const std::vector<MeshShape>*) {
        constexpr std::uint32_t kQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
        for (int i = 0; i < 8; ++i) s.vertex({(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f});
        for (const auto& q : kQuads) s.quad(q[0], q[1], q[2], q[3]);
    }
};

}  // namespace shapevo
