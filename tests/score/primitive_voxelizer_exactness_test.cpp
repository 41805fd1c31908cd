// Exactness of the voxelizer for every primitive kind: for 1,000 random primitives of each kind
// (cylinders, cones, spheres, meshes, roofs, paraboloids; random rotations, mirrored frames, tapers
// and roof fractions 0 and 1 (ridges, apexes), thin and flat sizes, grid-aligned placements whose
// surfaces pass exactly through voxel centres, positions leaving the grid) the bit rows and every count (occupied, inside, avoided, overlap, outside)
// equal a brute-force loop that applies the kind's inside test to every voxel centre; and that
// inside test agrees with the textbook formula (test::textbookDistance, long double) at every
// voxel centre farther than 1e-6 (local units) from the surface, so a wrong chord fails too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "random_primitives.hpp"
#include "shape/kinds/mesh.hpp"
#include "score/volume/voxelizer.hpp"

namespace shapevo {
namespace {

struct BruteForce {
    VoxelCounts counts;
    std::vector<std::uint64_t> bits;  ///< occupied bit rows, as Voxelizer::occupancy()
    long textbookChecked = 0;         ///< voxel centres also checked against the textbook formula
    long textbookMismatches = 0;      ///< ... where the kind's inside test disagreed with it
};

/// Farther than this from the surface (in the textbook formula's local units) the kind's inside
/// test must agree with test::textbookDistance: its chord is then not just self-consistent but
/// the solid of shape/primitive.hpp.
constexpr long double kTextbookMargin = 1e-6L;

/// Every voxel centre of the grid and its one-extent halo that could be inside `p`, tested one
/// by one with the kind's inside test. Boxes and round kinds: the ball through the box's corners
/// bounds them.
/// Meshes: rows within the vertices' bounding box; along a row, every centre between the
/// vertices (+-3 voxels) is tested, and beyond that one test stands for all (no crossing lies
/// there, so the ray test cannot change).
/// Every other kind's verdicts are also checked against the textbook formula away from the
/// surface (primitives with positive, finite half extents and a finite centre).
void bruteForceAdd(const Primitive& p, const std::vector<MeshShape>& meshes, const GridSpec& g,
                   std::vector<std::uint8_t>& hits, VoxelCounts& c, BruteForce& b) {
    const long n[3] = {g.nx, g.ny, g.nz};
    MeshSolid mesh;
    std::function<bool(double, double, double)> inside;
    double lo[3], hi[3];
    if (p.kind == PrimitiveKind::Mesh) {
        if (!mesh.place(p, meshes[test::meshIndexOf(p)])) return;
        for (int j = 0; j < 3; ++j) lo[j] = mesh.lo(j), hi[j] = mesh.hi(j);
        inside = [&](double x, double y, double z) { return mesh.contains(x, y, z); };
    } else {
        const double r = std::sqrt(double(p.half.x) * p.half.x + double(p.half.y) * p.half.y + double(p.half.z) * p.half.z);
        for (int j = 0; j < 3; ++j) lo[j] = p.centre[j] - r, hi[j] = p.centre[j] + r;
        inside = test::insideTest(p);
    }
    long first[3], last[3];
    for (int j = 0; j < 3; ++j) {
        if (std::isnan(lo[j]) || std::isnan(hi[j])) return;  // a NaN centre: no centre is inside
        first[j] = long(std::clamp(std::floor((lo[j] - g.origin[j]) / g.voxelSize) - 3, double(-n[j]), double(2 * n[j])));
        last[j] = long(std::clamp(std::ceil((hi[j] - g.origin[j]) / g.voxelSize) + 3, double(-n[j] - 1), double(2 * n[j] - 1)));
    }
    auto cover = [&](long x, long y, long z) {
        if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) {
            ++c.outside;
            return;
        }
        auto& h = hits[(std::size_t(z) * g.ny + y) * g.nx + x];
        if (h < 2) ++h;
    };
    const bool isMesh = p.kind == PrimitiveKind::Mesh;
    bool textbook = !isMesh;
    for (int j = 0; j < 3; ++j)
        textbook = textbook && std::isfinite(p.centre[j]) && p.half[j] != 0.0f && std::isfinite(p.half[j]);
    for (long z = first[2]; z <= last[2]; ++z)
        for (long y = first[1]; y <= last[1]; ++y) {
            const double cy = g.centre(1, y), cz = g.centre(2, z);
            if (isMesh && first[0] > -n[0] && inside(g.centre(0, first[0] - 1), cy, cz))
                for (long x = -n[0]; x < first[0]; ++x) cover(x, y, z);
            for (long x = first[0]; x <= last[0]; ++x) {
                const bool in = inside(g.centre(0, x), cy, cz);
                if (in) cover(x, y, z);
                if (!textbook) continue;
                const double w[3] = {g.centre(0, x), cy, cz};
                const long double d = test::textbookDistance(p, test::localCoordinates(p, w));
                if (!(std::fabs(d) > kTextbookMargin)) continue;
                ++b.textbookChecked;
                b.textbookMismatches += in != (d < 0);
            }
            if (isMesh && last[0] < 2 * n[0] - 1 && inside(g.centre(0, last[0] + 1), cy, cz))
                for (long x = last[0] + 1; x <= 2 * n[0] - 1; ++x) cover(x, y, z);
        }
}

BruteForce bruteForce(const Geometry& geometry, const VolumeTarget& t) {
    const GridSpec& g = t.grid;
    BruteForce b;
    b.bits.assign(g.words(), 0);
    std::vector<std::uint8_t> hits(std::size_t(g.nx) * g.ny * g.nz, 0);
    for (const Primitive& p : geometry.primitives) bruteForceAdd(p, *geometry.meshes, g, hits, b.counts, b);
    test::countHits(hits, t, b.counts, &b.bits);
    return b;
}

struct Totals {
    std::uint64_t occupied = 0, outside = 0, overlap = 0, empty = 0;
    long textbookChecked = 0;
};

/// `primitives` random primitives of `kinds` (cycled), in models of one to four, compared with
/// the brute force: bit rows after add(), then every count of score(). `turned`: every frame is
/// turned about one grid axis instead.
Totals compareWithBruteForce(const std::vector<PrimitiveKind>& kinds, const GridSpec& grid, int primitives,
                             std::uint64_t seed, bool gridAligned = false, bool turned = false) {
    Rng rng(seed);
    const VolumeTarget target = test::randomTarget(grid, rng);
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    Voxelizer vox(grid);
    Geometry geometry;
    geometry.meshes = &meshes;
    Totals totals;
    for (int made = 0, model = 0; made < primitives; ++model) {
        geometry.primitives.clear();
        const int n = std::min(1 + int(rng.below(4)), primitives - made);
        for (int i = 0; i < n; ++i, ++made) {
            Primitive p = test::randomPrimitive(kinds[std::size_t(made) % kinds.size()], grid, rng, 2, gridAligned);
            if (turned) p.axes = test::randomTurnAboutGridAxis(rng);
            if (i > 0 && rng.below(2))  // near the previous one, so that they overlap
                for (int j = 0; j < 3; ++j) p.centre[j] = geometry.primitives.back().centre[j] + float(0.4 * rng.uniform() - 0.2);
            geometry.primitives.push_back(p);
        }
        const BruteForce slow = bruteForce(geometry, target);
        EXPECT_EQ(slow.textbookMismatches, 0) << "model " << model << ": the inside test is not the textbook solid";
        VoxelCounts added;
        for (const Primitive& p : geometry.primitives) vox.add(p, geometry.meshes, added);
        const auto& bits = vox.occupancy();
        const auto diff = std::mismatch(bits.begin(), bits.end(), slow.bits.begin());
        const bool sameBits = diff.first == bits.end();
        EXPECT_TRUE(sameBits) << "model " << model << ": bit rows differ at word " << (diff.first - bits.begin()) << ": "
                              << std::hex << (sameBits ? 0 : *diff.first) << " vs " << (sameBits ? 0 : *diff.second);
        EXPECT_EQ(added.outside, slow.counts.outside) << "model " << model;
        vox.clear();
        VoxelCounts fast = vox.score(geometry, target);
        fast.rows = 0;
        EXPECT_EQ(fast, slow.counts) << "model " << model << " occupied " << fast.occupied << " vs " << slow.counts.occupied
                                     << ", overlap " << fast.overlap << " vs " << slow.counts.overlap << ", outside "
                                     << fast.outside << " vs " << slow.counts.outside;
        if (!sameBits || added.outside != slow.counts.outside || !(fast == slow.counts) || slow.textbookMismatches != 0)
            return totals;  // one report is enough
        totals.textbookChecked += slow.textbookChecked;
        totals.occupied += slow.counts.occupied;
        totals.outside += slow.counts.outside;
        totals.overlap += slow.counts.overlap;
        totals.empty += slow.counts.occupied + slow.counts.outside == 0 ? 1 : 0;
    }
    return totals;
}

GridSpec testGrid() {
    GridSpec grid;
    grid.origin = {-1.3, -0.7, 0.25};
    grid.voxelSize = 0.1;
    grid.nx = 70;  // two words per row, the second partly used
    grid.ny = 23;
    grid.nz = 17;
    return grid;
}

/// The random models really exercise every term (and are not mostly empty).
/// (`textbook`: the voxel centres checked against the textbook formula were many too; not for meshes.)
void expectEveryTerm(const Totals& t, bool textbook = true) {
    if (textbook) {
        EXPECT_GT(t.textbookChecked, 100000);
    }
    EXPECT_GT(t.occupied, 20000u);
    EXPECT_GT(t.outside, 20000u);
    EXPECT_GT(t.overlap, 1000u);
    EXPECT_LT(t.empty, 100u);
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomCylindersMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Cylinder}, testGrid(), 1000, 11));
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomConesWithTapersZeroToOneMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Cone}, testGrid(), 1000, 12));
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomSpheresMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Sphere}, testGrid(), 1000, 13));
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomOctahedraAndLPrismsMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Mesh}, testGrid(), 1000, 14), false);
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomRoofsWithRidgesApexesAndFrustaMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Roof}, testGrid(), 1000, 31));
}

TEST(PrimitiveVoxelizerExactness, ThousandRandomParaboloidsMatchBruteForceVoxelByVoxel) {
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Paraboloid}, testGrid(), 1000, 32));
}

TEST(PrimitiveVoxelizerExactness, ThousandBoxesTurnedAboutOneGridAxisMatchBruteForce) {
    // The box voxelizer intersects the slabs without a y component once per z: turns about y
    // (buildings), x and z, by quarter turns, almost quarter turns and any angle.
    expectEveryTerm(compareWithBruteForce({PrimitiveKind::Box}, testGrid(), 1000, 34, false, true));
}

TEST(PrimitiveVoxelizerExactness, ModelsMixingAllKindsMatchBruteForceIncludingOverlapsBetweenKinds) {
    const std::vector<PrimitiveKind> all = {PrimitiveKind::Box, PrimitiveKind::Cylinder, PrimitiveKind::Cone,
                                            PrimitiveKind::Sphere, PrimitiveKind::Mesh};
    expectEveryTerm(compareWithBruteForce(all, testGrid(), 1000, 15));
    const std::vector<PrimitiveKind> withNew = {PrimitiveKind::Box,  PrimitiveKind::Cylinder, PrimitiveKind::Cone,
                                                PrimitiveKind::Sphere, PrimitiveKind::Mesh,   PrimitiveKind::Roof,
                                                PrimitiveKind::Paraboloid};
    expectEveryTerm(compareWithBruteForce(withNew, testGrid(), 1400, 33));
}

TEST(PrimitiveVoxelizerExactness, GridAlignedPrimitivesWithSurfacesThroughVoxelCentresMatchBruteForce) {
    // Axis-aligned, centred on voxel centres or corners, half extents in half voxels: many row
    // ends fall exactly on a voxel centre, where only the exact test can decide.
    for (PrimitiveKind kind : {PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Sphere, PrimitiveKind::Mesh,
                               PrimitiveKind::Roof, PrimitiveKind::Paraboloid}) {
        SCOPED_TRACE(int(kind));
        const int primitives = kind == PrimitiveKind::Paraboloid ? 1500 : 1000;  // half its cylinder's volume
        expectEveryTerm(compareWithBruteForce({kind}, testGrid(), primitives, 16 + std::uint64_t(kind), true), kind != PrimitiveKind::Mesh);
    }
}

TEST(PrimitiveVoxelizerExactness, FarHugeTinyNegativeNonFiniteAndNearlyPerpendicularPrimitivesAreSafeAndExact) {
    GridSpec grid;
    grid.origin = {-1.0, -1.0, -1.0};
    grid.voxelSize = 0.1;
    grid.nx = grid.ny = grid.nz = 20;
    Rng rng(77);
    const VolumeTarget target = test::randomTarget(grid, rng);
    const std::vector<MeshShape> meshes = {test::octahedron(), test::lPrism()};
    Voxelizer vox(grid);
    Geometry geometry;
    geometry.meshes = &meshes;
    const float c = std::cos(1e-5f), s = std::sin(1e-5f);
    const glm::mat3 tilted(c, 0, s, 0, 1, 0, -s, 0, c), rotated(0.8f, 0.6f, 0, -0.6f, 0.8f, 0, 0, 0, 1);
    std::vector<Primitive> cases;
    std::vector<std::size_t> coverEverything;  // cases that cover the grid and the whole halo
    for (PrimitiveKind kind : {PrimitiveKind::Cylinder, PrimitiveKind::Cone, PrimitiveKind::Sphere, PrimitiveKind::Mesh,
                               PrimitiveKind::Roof, PrimitiveKind::Paraboloid}) {
        for (std::uint16_t mesh = 0; mesh < (kind == PrimitiveKind::Mesh ? 2 : 1); ++mesh) {
            Primitive p;
            p.kind = kind;
            float taper = 0.0f, taperZ = 1.0f;
            test::setKindParams(p, taper, taperZ, mesh);
            p.axes = rotated;
            p.centre = {0, 0, 1e20f};  // far away: must not overflow or loop
            cases.push_back(p);
            p.centre = {0.05f, -0.05f, 0.1f};
            p.half = {1e3f, 1e3f, 1e3f};  // huge
            if (!(kind == PrimitiveKind::Mesh && mesh == 1)) coverEverything.push_back(cases.size());  // an L leaves a quarter
            cases.push_back(p);
            p.half = {-0.3f, -0.5f, -0.4f};  // negative half extents mean the same solid
            cases.push_back(p);
            p.half = {0.3f, 1e-30f, 0.4f};  // tiny but not zero
            cases.push_back(p);
            p.half = {0.3f, INFINITY, 0.4f};
            cases.push_back(p);
            p.half = {0.3f, 0.5f, 0.4f};
            p.centre.x = NAN;
            cases.push_back(p);
            for (int i = 0; i < 20; ++i) {  // a tiny tilt: rows almost along an axis or a face
                p.axes = tilted;
                taper = float(rng.uniform());
                if (kind == PrimitiveKind::Roof) taperZ = float(rng.uniform());
                test::setKindParams(p, taper, taperZ, mesh);
                p.centre = {float(rng.uniform() - 0.5), float(rng.uniform() - 0.5), float(rng.uniform() - 0.5)};
                p.half = {float(0.1 + rng.uniform()), float(0.1 + rng.uniform()), float(0.1 + rng.uniform())};
                cases.push_back(p);
            }
        }
    }
    std::uint64_t covered = 0;
    for (std::size_t m = 0; m < cases.size(); ++m) {
        geometry.primitives = {cases[m]};
        VoxelCounts fast = vox.score(geometry, target);
        const BruteForce slow = bruteForce(geometry, target);
        fast.rows = 0;
        EXPECT_EQ(fast, slow.counts) << "case " << m << " kind " << int(cases[m].kind);
        EXPECT_EQ(slow.textbookMismatches, 0) << "case " << m << " kind " << int(cases[m].kind);
        covered += slow.counts.occupied;
        if (std::find(coverEverything.begin(), coverEverything.end(), m) != coverEverything.end()) {
            EXPECT_EQ(fast.occupied, 8000u) << "case " << m;
            EXPECT_EQ(fast.outside, 27u * 8000u - 8000u) << "case " << m;
        }
    }
    EXPECT_GT(covered, 100000u);
}

TEST(PrimitiveVoxelizerExactness, MeshPrimitiveWithoutItsMeshCoversNothing) {
    const GridSpec grid = testGrid();
    Rng rng(3);
    const VolumeTarget target = test::randomTarget(grid, rng);
    Voxelizer vox(grid);
    Geometry geometry;
    Primitive p;
    p.kind = PrimitiveKind::Mesh;
    p.centre = {2.0f, 0.5f, 1.0f};
    geometry.primitives = {p};
    EXPECT_EQ(vox.score(geometry, target), VoxelCounts{});  // no meshes at all
    const std::vector<MeshShape> meshes = {test::octahedron()};
    geometry.meshes = &meshes;
    setParams<MeshKind>(geometry.primitives[0], {1});  // out of range
    EXPECT_EQ(vox.score(geometry, target), VoxelCounts{});
    setParams<MeshKind>(geometry.primitives[0], {0});
    EXPECT_GT(vox.score(geometry, target).occupied, 0u);
}

}  // namespace
}  // namespace shapevo
