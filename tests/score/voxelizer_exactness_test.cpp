// Exact-count tests: the bit-row voxelizer agrees with a brute-force voxel-centre test on every
// count (occupied, inside, avoided, overlap, outside) for 1,000 random models, including rotated,
// mirrored, axis-aligned and boundary-aligned boxes and boxes that leave the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "genome/random.hpp"
#include "shape/box_frame.hpp"
#include "score/volume/voxelizer.hpp"

#include "random_primitives.hpp"

namespace shapevo {
namespace {

using test::randomTarget;

Geometry geometryOf(std::vector<Primitive> primitives) {
    Geometry g;
    g.primitives = std::move(primitives);
    return g;
}

Primitive randomBox(const GridSpec& grid, Rng& rng) {
    Primitive p;
    const double ext[3] = {grid.nx * grid.voxelSize, grid.ny * grid.voxelSize, grid.nz * grid.voxelSize};
    const int style = int(rng.below(4));
    for (int j = 0; j < 3; ++j) {
        if (style == 3) {  // centre on a voxel centre, half extents in half voxels: faces through centres
            p.centre[j] = float(grid.centre(j, long(rng.below(std::uint32_t(ext[j] / grid.voxelSize)))));
            p.half[j] = float(grid.voxelSize * 0.5 * double(1 + rng.below(12)));
        } else {
            p.centre[j] = float(grid.origin[j] - 0.3 * ext[j] + 1.6 * ext[j] * rng.uniform());
            p.half[j] = float(0.02 + 0.6 * rng.uniform());
        }
    }
    if (style <= 1) p.axes = test::randomRotation(rng);
    if (rng.below(4) == 0) p.axes[int(rng.below(3))] *= -1.0f;  // a mirrored frame
    return p;
}

/// Brute force: every lattice point of the grid and its one-extent halo, tested one by one.
VoxelCounts bruteForce(const std::vector<Primitive>& prims, const VolumeTarget& t) {
    const GridSpec& g = t.grid;
    VoxelCounts c;
    std::vector<std::uint8_t> hits(std::size_t(g.nx) * g.ny * g.nz, 0);
    for (const Primitive& p : prims) {
        const BoxFrame b = BoxFrame::from(p);
        const double r = std::fabs(b.h[0]) + std::fabs(b.h[1]) + std::fabs(b.h[2]);  // >= the true reach
        long lo[3], hi[3];
        const long n[3] = {g.nx, g.ny, g.nz};
        for (int j = 0; j < 3; ++j) {
            // clamped into the halo as doubles: a box 1e20 away must not overflow the conversion
            const double l = std::floor((b.c[j] - r - g.origin[j]) / g.voxelSize) - 2;
            const double h = std::ceil((b.c[j] + r - g.origin[j]) / g.voxelSize) + 2;
            lo[j] = long(std::clamp(l, double(-n[j]), double(2 * n[j])));
            hi[j] = long(std::clamp(h, double(-n[j] - 1), double(2 * n[j] - 1)));
        }
        for (long z = lo[2]; z <= hi[2]; ++z)
            for (long y = lo[1]; y <= hi[1]; ++y)
                for (long x = lo[0]; x <= hi[0]; ++x) {
                    if (!b.contains(g.centre(0, x), g.centre(1, y), g.centre(2, z))) continue;
                    if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) {
                        ++c.outside;
                        continue;
                    }
                    auto& h = hits[(std::size_t(z) * g.ny + y) * g.nx + x];
                    if (h < 2) ++h;
                }
    }
    test::countHits(hits, t, c);
    return c;
}

TEST(VoxelizerExactness, MatchesBruteForceVoxelCentreTestOnAThousandRandomModels) {
    Rng rng(2024);
    GridSpec grid;
    grid.origin = {-1.3, -0.7, 0.25};
    grid.voxelSize = 0.1;
    grid.nx = 70;  // two words per row, the second partly used
    grid.ny = 23;
    grid.nz = 17;
    const VolumeTarget target = randomTarget(grid, rng);
    Voxelizer vox(grid);
    std::uint64_t totalOccupied = 0, totalOutside = 0, totalOverlap = 0;
    for (int model = 0; model < 1000; ++model) {
        std::vector<Primitive> prims;
        const int n = 1 + int(rng.below(8));
        for (int i = 0; i < n; ++i) prims.push_back(randomBox(grid, rng));
        VoxelCounts fast = vox.score(geometryOf(prims), target);
        const VoxelCounts slow = bruteForce(prims, target);
        fast.rows = 0;
        ASSERT_EQ(fast.occupied, slow.occupied) << "model " << model;
        ASSERT_EQ(fast.inside, slow.inside) << "model " << model;
        ASSERT_EQ(fast.avoided, slow.avoided) << "model " << model;
        ASSERT_EQ(fast.overlap, slow.overlap) << "model " << model;
        ASSERT_EQ(fast.outside, slow.outside) << "model " << model;
        totalOccupied += slow.occupied;
        totalOutside += slow.outside;
        totalOverlap += slow.overlap;
    }
    // The random models really exercise every term.
    EXPECT_GT(totalOccupied, 100000u);
    EXPECT_GT(totalOutside, 10000u);
    EXPECT_GT(totalOverlap, 1000u);
}

TEST(VoxelizerExactness, FarHugeNegativeAndNearlyPerpendicularBoxesAreSafeAndExact) {
    Rng rng(77);
    GridSpec grid;
    grid.origin = {-1.0, -1.0, -1.0};
    grid.voxelSize = 0.1;
    grid.nx = grid.ny = grid.nz = 20;
    const VolumeTarget target = randomTarget(grid, rng);
    Voxelizer vox(grid);
    const float c = std::cos(1e-5f), s = std::sin(1e-5f);  // a tiny tilt: slope ~1e-5, the bisection path
    std::vector<std::vector<Primitive>> models;
    Primitive far;  // rotated and 1e20 away: must not overflow or loop
    far.axes = glm::mat3(0.8f, 0.6f, 0, -0.6f, 0.8f, 0, 0, 0, 1);
    far.centre = {0, 0, 1e20f};
    models.push_back({far});
    Primitive huge;  // covers the grid and the whole halo
    huge.axes = far.axes;
    huge.half = {1e3f, 1e3f, 1e3f};
    models.push_back({huge});
    Primitive negative;  // negative half extents mean the same box
    negative.centre = {0.05f, 0.05f, 0.05f};
    negative.half = {-0.3f, -0.2f, -0.25f};
    models.push_back({negative});
    for (int i = 0; i < 50; ++i) {
        Primitive tilted;
        tilted.axes = glm::mat3(c, 0, s, 0, 1, 0, -s, 0, c);
        tilted.centre = {float(rng.uniform() - 0.5), float(rng.uniform() - 0.5), float(rng.uniform() - 0.5)};
        tilted.half = {float(0.1 + rng.uniform()), float(0.1 + rng.uniform()), float(0.1 + rng.uniform())};
        models.push_back({tilted});
    }
    for (std::size_t m = 0; m < models.size(); ++m) {
        VoxelCounts fast = vox.score(geometryOf(models[m]), target);
        const VoxelCounts slow = bruteForce(models[m], target);
        fast.rows = 0;
        EXPECT_EQ(fast, slow) << "model " << m;
    }
}

TEST(VoxelizerExactness, AxisAlignedUnitCubeCoversExactlyTheExpectedVoxels) {
    GridSpec grid;
    grid.origin = {0, 0, 0};
    grid.voxelSize = 0.25;
    grid.nx = grid.ny = grid.nz = 8;
    VolumeTarget t;
    t.grid = grid;
    t.fill.assign(grid.words(), 0);
    t.avoid.assign(grid.words(), 0);
    Voxelizer vox(grid);
    Primitive p;
    p.centre = {1.0f, 1.0f, 1.0f};
    p.half = {0.5f, 0.5f, 0.5f};  // [0.5, 1.5]^3 holds centres 0.625 .. 1.375: 4 per axis
    const VoxelCounts c = vox.score(geometryOf({p}), t);
    EXPECT_EQ(c.occupied, 64u);
    EXPECT_EQ(c.outside, 0u);
    EXPECT_EQ(c.overlap, 0u);
    // the same box twice overlaps itself everywhere
    const VoxelCounts twice = vox.score(geometryOf({p, p}), t);
    EXPECT_EQ(twice.overlap, 64u);
}

}  // namespace
}  // namespace shapevo
