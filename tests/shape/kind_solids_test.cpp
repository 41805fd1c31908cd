// The voxel-centre inside tests are the solids of shape/primitive.hpp (shape/kinds/*.hpp): they agree with the
// textbook formulas (evaluated in long double in the primitive's local coordinates) everywhere
// except within 1e-9 of the surface; closed meshes cross every row an even number of times, even
// through vertices and edges; voxel counts approach the analytic volumes; and chordInterval is
// exact when a chord ends exactly on a voxel centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "../score/random_primitives.hpp"
#include "shape/kinds/mesh.hpp"
#include "score/volume/voxelizer.hpp"

namespace shapevo {
namespace {

using test::Local;

/// Signed "distance" of local point u from the surface of primitive p (negative inside), in the
/// textbook form of primitive.hpp (test::textbookDistance; the two meshes here).
long double textbook(const Primitive& p, const Local& u) {
    if (p.kind != PrimitiveKind::Mesh) return test::textbookDistance(p, u);
    // meshes: 0 = octahedron |u|_1 <= 1, 1 = L-prism
    if (test::meshIndexOf(p) == 0) return std::fabs(u[0]) + std::fabs(u[1]) + std::fabs(u[2]) - 1;
    const long double lower = std::max(std::fabs(u[0]) - 1, std::fabs(u[1] + 0.5L) - 0.5L);  // [-1,1] x [-1,0]
    const long double left = std::max(std::fabs(u[0] + 0.5L) - 0.5L, std::fabs(u[1]) - 1);   // [-1,0] x [-1,1]
    return std::max(std::min(lower, left), std::fabs(u[2]) - 1);
}

/// Local coordinates of world point w. Boxes and round kinds project onto the frame's axes (as
/// BoxFrame does); meshes are placed by the forward map w = c + sum_k axis_k * h_k * u_k, so
/// their local coordinates invert it. With float axes (orthonormal to ~1e-7) the two differ.
Local toLocal(const Primitive& p, const double w[3]) {
    Local u, d;
    for (int j = 0; j < 3; ++j) d[j] = (long double)w[j] - (long double)p.centre[j];
    if (p.kind != PrimitiveKind::Mesh) {
        for (int k = 0; k < 3; ++k) {
            long double s = 0;
            for (int j = 0; j < 3; ++j) s += (long double)p.axes[k][j] * d[j];
            u[k] = s / std::fabs((long double)p.half[k]);
        }
        return u;
    }
    long double m[3][3];  // m[j][k] = axis_k[j] * h_k
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) m[j][k] = (long double)p.axes[k][j] * std::fabs((long double)p.half[k]);
    auto det3 = [](const long double (&a)[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const long double det = det3(m);
    for (int k = 0; k < 3; ++k) {  // Cramer's rule
        long double mk[3][3];
        for (int j = 0; j < 3; ++j)
            for (int l = 0; l < 3; ++l) mk[j][l] = l == k ? d[j] : m[j][l];
        u[k] = det3(mk) / det;
    }
    return u;
}

/// Random points around p: uniform in its box grown by 30%, or (half of them) moved onto the
/// surface along the ray from the centre and then off it by a relative 1e-8 .. 1e-2.
void checkAgainstTextbook(const Primitive& p, const std::function<bool(double, double, double)>& inside, Rng& rng,
                          long& checked, long& in, long& out) {
    for (int i = 0; i < 200; ++i) {
        Local u;
        for (auto& v : u) v = 2.6L * (long double)rng.uniform() - 1.3L;
        if (rng.below(2)) {
            long double lo = 0, hi = 64;  // textbook(t * u) changes sign once on [0, hi] (star-shaped about 0)
            for (int it = 0; it < 64; ++it) {
                const long double m = (lo + hi) / 2;
                (textbook(p, {m * u[0], m * u[1], m * u[2]}) <= 0 ? lo : hi) = m;
            }
            const long double s = lo * (1 + (rng.below(2) ? 1 : -1) * std::pow(10.0L, -8 + 6 * (long double)rng.uniform()));
            for (auto& v : u) v *= s;
        }
        double w[3];
        for (int j = 0; j < 3; ++j) {
            long double x = p.centre[j];
            for (int k = 0; k < 3; ++k) x += (long double)p.axes[k][j] * std::fabs((long double)p.half[k]) * u[k];
            w[j] = double(x);
        }
        const long double g = textbook(p, toLocal(p, w));
        if (std::fabs(g) <= 1e-9L) continue;
        ++checked;
        (g < 0 ? in : out) += 1;
        const Local ul = toLocal(p, w);
        ASSERT_EQ(inside(w[0], w[1], w[2]), g < 0) << "kind " << int(p.kind) << " taper " << test::taperOf(p) << " taperZ " << test::taperZOf(p)
                                                   << " mesh " << test::meshIndexOf(p)
                                                   << " g " << double(g) << " at local " << double(ul[0]) << " "
                                                   << double(ul[1]) << " " << double(ul[2]);
    }
}

GridSpec smallGrid() {
    GridSpec grid;
    grid.origin = {-1.3, -0.7, 0.25};
    grid.voxelSize = 0.1;
    grid.nx = 70;
    grid.ny = 23;
    grid.nz = 17;
    return grid;
}

TEST(PrimitiveShapes, RoundInsideTestsAgreeWithTheTextbookFormulasAwayFromTheSurface) {
    Rng rng(5);
    const GridSpec grid = smallGrid();
    for (PrimitiveKind kind : {PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Sphere, PrimitiveKind::Roof,
                               PrimitiveKind::Paraboloid}) {
        long checked = 0, in = 0, out = 0;
        for (int n = 0; n < 1000; ++n) {
            Primitive p = test::randomPrimitive(kind, grid, rng);
            if (rng.below(8) == 0) p.half[int(rng.below(3))] = float(1e-4 * rng.uniform() + 1e-6);  // thin
            if (!(p.half.x > 0 && p.half.y > 0 && p.half.z > 0)) continue;
            checkAgainstTextbook(p, test::insideTest(p), rng, checked, in, out);
            if (testing::Test::HasFatalFailure()) return;
        }
        EXPECT_GT(checked, 170000) << "kind " << int(kind);
        EXPECT_GT(in, 50000) << "kind " << int(kind);
        EXPECT_GT(out, 50000) << "kind " << int(kind);
    }
}

TEST(PrimitiveShapes, MeshRayTestAgreesWithTheOctahedronAndLPrismFormulasAwayFromTheSurface) {
    Rng rng(6);
    const GridSpec grid = smallGrid();
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    MeshSolid mesh;
    long checked = 0, in = 0, out = 0;
    for (int n = 0; n < 1000; ++n) {
        const Primitive p = test::randomPrimitive(PrimitiveKind::Mesh, grid, rng, 2);
        if (!mesh.place(p, meshes[test::meshIndexOf(p)])) continue;
        checkAgainstTextbook(p, [&](double x, double y, double z) { return mesh.contains(x, y, z); }, rng, checked, in, out);
        if (testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GT(checked, 170000);
    EXPECT_GT(in, 50000);
    EXPECT_GT(out, 50000);
}

TEST(PrimitiveShapes, ClosedMeshesCrossEveryRowAnEvenNumberOfTimesEvenThroughVerticesAndEdges) {
    Rng rng(7);
    GridSpec grid = smallGrid();
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    MeshSolid mesh;
    std::vector<RowCrossing> crossings;
    long rows = 0, crossed = 0, odd = 0;
    for (int n = 0; n < 2000; ++n) {
        // grid-aligned placements put vertices and edges exactly on the rows
        const Primitive p = test::randomPrimitive(PrimitiveKind::Mesh, grid, rng, 2, n % 2 == 0);
        if (!mesh.place(p, meshes[test::meshIndexOf(p)])) continue;
        crossings.clear();
        const long y0 = -grid.ny, y1 = 2 * grid.ny - 1, z0 = -grid.nz, z1 = 2 * grid.nz - 1;
        mesh.collectCrossings(grid, y0, y1, z0, z1, crossings);
        std::vector<int> perRow(std::size_t((y1 - y0 + 1) * (z1 - z0 + 1)), 0);
        for (const RowCrossing& c : crossings) ++perRow[c.row];
        for (int count : perRow) {
            rows += count > 0;
            crossed += count;
            odd += count % 2;
        }
    }
    EXPECT_EQ(odd, 0) << "rows crossing an odd number of triangles, of " << rows;
    EXPECT_GT(rows, 50000);
    EXPECT_GT(crossed, 2 * rows);
}

TEST(PrimitiveShapes, VoxelCountsOfRotatedPrimitivesApproachTheAnalyticVolumes) {
    GridSpec grid;
    grid.origin = {-3, -3, -3};
    grid.voxelSize = 0.05;
    grid.nx = grid.ny = grid.nz = 120;
    VolumeTarget target;
    target.grid = grid;
    target.fill.assign(grid.words(), 0);
    target.avoid.assign(grid.words(), 0);
    Voxelizer vox(grid);
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    Geometry geometry;
    geometry.meshes = &meshes;
    Rng rng(8);
    struct Case {
        PrimitiveKind kind;
        float taper;
        std::uint16_t mesh;
        double volume;  ///< per unit of half-extent product h.x * h.y * h.z
        float taperZ = 1;
    };
    // A roof: integral over u.y of 4 rx rz = 8 (1 + (a + b) / 2 + a b / 3), a = tx - 1, b = tz - 1.
    auto roof = [](double tx, double tz) { return 8 * (1 + (tx - 1 + tz - 1) / 2 + (tx - 1) * (tz - 1) / 3); };
    const double pi = M_PI;
    const Case cases[] = {{PrimitiveKind::Box, 1, 0, 8},
                          {PrimitiveKind::Sphere, 1, 0, 4 * pi / 3},
                          {PrimitiveKind::Cylinder, 1, 0, 2 * pi},
                          {PrimitiveKind::Cone, 0, 0, 2 * pi / 3},
                          {PrimitiveKind::Cone, 0.5f, 0, 2 * pi / 3 * (1 + 0.5 + 0.25)},
                          {PrimitiveKind::Cone, 1, 0, 2 * pi},
                          {PrimitiveKind::Mesh, 1, 0, 4.0 / 3},
                          {PrimitiveKind::Mesh, 1, 1, 6},
                          {PrimitiveKind::Roof, 1, 0, 8},
                          {PrimitiveKind::Roof, 1, 0, 4, 0},
                          {PrimitiveKind::Roof, 0, 0, 8.0 / 3, 0},
                          {PrimitiveKind::Roof, 0.3f, 0, roof(0.3f, 0.6f), 0.6f},
                          {PrimitiveKind::Paraboloid, 1, 0, pi}};
    for (const Case& c : cases) {
        Primitive p;
        p.kind = c.kind;
        test::setKindParams(p, c.taper, c.taperZ, c.mesh);
        p.axes = test::randomRotation(rng);
        p.axes[1] *= -1.0f;  // mirrored
        p.centre = {0.013f, -0.021f, 0.007f};
        p.half = {1.7f, 2.1f, 1.3f};
        geometry.primitives = {p};
        const VoxelCounts counts = vox.score(geometry, target);
        const double measured = double(counts.occupied + counts.outside) * std::pow(grid.voxelSize, 3);
        const double expected = c.volume * 1.7 * 2.1 * 1.3;
        EXPECT_NEAR(measured / expected, 1.0, 0.01) << "kind " << int(c.kind) << " taper " << c.taper << " mesh " << c.mesh
                                                    << " taperZ " << c.taperZ;
        EXPECT_EQ(counts.overlap, 0u);
    }
}

TEST(ChordInterval, IsExactWhenTheChordEndsExactlyOnVoxelCentresOrOneUlpAway) {
    Rng rng(9);
    const GridSpec grid = smallGrid();
    long exactEnds = 0;
    for (int n = 0; n < 100000; ++n) {
        const double cx = grid.origin[0] + 7.0 * rng.uniform();
        const long i = long(rng.below(70)), j = i + long(rng.below(10));
        Chord ch{grid.centre(0, i) - cx, grid.centre(0, j) - cx};  // what the test itself computes
        const int nudge = int(rng.below(3));
        if (nudge == 1) ch.lo = std::nextafter(ch.lo, INFINITY), ch.hi = std::nextafter(ch.hi, -INFINITY);
        if (nudge == 2) ch.lo = std::nextafter(ch.lo, -INFINITY), ch.hi = std::nextafter(ch.hi, INFINITY);
        long lo = 0, hi = -1, blo = 0, bhi = -1;
        const bool any = chordInterval(ch, cx, grid, -70, 139, lo, hi);
        bool seen = false;
        for (long k = -70; k <= 139; ++k)
            if (ch.contains(grid.centre(0, k) - cx)) {
                if (!seen) blo = k;
                bhi = k;
                seen = true;
            }
        ASSERT_EQ(any, seen) << n;
        if (seen) {
            ASSERT_EQ(lo, blo) << n;
            ASSERT_EQ(hi, bhi) << n;
        }
        exactEnds += nudge == 0;
    }
    EXPECT_GT(exactEnds, 30000);
}

}  // namespace
}  // namespace shapevo
