// Tests for writeTargetVdb (metadata, no clobbering, bad arguments) and loadVolumeTarget
// (exact inside counts, deep interior, override grids, avoid bits, hash, bad files).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "../mesh/cube_mesh.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"
#include "score/volume/vdb_target_file.hpp"
#include "../test_support.hpp"
#include "grid_bits.hpp"

namespace shapevo {
namespace {

using test::boxMesh;
using test::cubeMesh;
using test::TempDir;
using test::writeFile;

/// Brute force: is the centre of dense voxel (i,j,k) strictly inside the box? Fails the test if
/// a centre lies within 1e-6 of the box surface, where "inside" would be ambiguous.
bool centreInside(const GridSpec& g, int i, int j, int k, const glm::dvec3& lo, const glm::dvec3& hi) {
    const double c[3] = {g.centre(0, i), g.centre(1, j), g.centre(2, k)};
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        EXPECT_GT(std::min(std::fabs(c[a] - lo[a]), std::fabs(c[a] - hi[a])), 1e-6) << "centre on the surface";
        inside = inside && c[a] > lo[a] && c[a] < hi[a];
    }
    return inside;
}

/// Checks every dense voxel against the brute-force box test; returns the expected count.
std::uint64_t expectBitsMatchBox(const std::vector<std::uint64_t>& bits, const GridSpec& g, const glm::dvec3& lo,
                                 const glm::dvec3& hi) {
    std::uint64_t expected = 0, mismatches = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const bool want = centreInside(g, i, j, k, lo, hi);
                expected += want;
                mismatches += want != test::gridBit(bits, g, i, j, k);
            }
    EXPECT_EQ(mismatches, 0u);
    return expected;
}

TEST(VdbTargetFile, WrittenCubeBakesToExactCountOfVoxelCentresInside) {
    TempDir dir;
    const std::string path = dir.file("cube.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", path);
    const VolumeTarget t = loadVolumeTarget({{path}});
    const std::uint64_t expected = expectBitsMatchBox(t.fill, t.grid, glm::dvec3(-1), glm::dvec3(1));
    EXPECT_EQ(expected, 343u);  // centres at 0, +-0.3, +-0.6, +-0.9 on each axis
    EXPECT_EQ(t.fillCount, expected);
    EXPECT_EQ(t.avoidCount, 0u);
    EXPECT_DOUBLE_EQ(t.grid.voxelSize, 0.3);
}

TEST(VdbTargetFile, EachFileIsHashedAsItIsReadAsHashFileHashesIt) {
    TempDir dir;
    const std::string cube = dir.file("cube.vdb"), box = dir.file("box.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", cube);
    writeTargetVdb(boxMesh({-1, -0.5f, -0.25f}, {1, 0.5f, 0.25f}), 0.3, "box.obj", box);
    const VolumeTarget t = loadVolumeTarget({{cube}, {box, true}});
    ASSERT_EQ(t.fileHashes.size(), 2u);
    EXPECT_EQ(t.fileHashes[0], hashFile(cube).hash);
    EXPECT_EQ(t.fileHashes[1], hashFile(box).hash);
}

TEST(VdbTargetFile, AutomaticGridIsActiveBoundsPaddedByAQuarterOnTheTargetLattice) {
    TempDir dir;
    const std::string path = dir.file("box.vdb");
    writeTargetVdb(boxMesh({-1, -0.5f, -0.25f}, {1, 0.5f, 0.25f}), 0.3, "box.obj", path);
    const GridSpec g = loadVolumeTarget({{path}}).grid;

    openvdb::initialize();
    openvdb::io::File file(path);
    file.open();
    const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.getGrids()->front());
    const openvdb::CoordBBox active = grid->evalActiveVoxelBoundingBox();
    const openvdb::Vec3d lo = (active.min().asVec3d() - 0.5) * 0.3, hi = (active.max().asVec3d() + 0.5) * 0.3;
    const openvdb::Vec3d extent = hi - lo;
    const double pad = 0.25 * std::max({extent[0], extent[1], extent[2]});
    const int n[3] = {g.nx, g.ny, g.nz};
    for (int a = 0; a < 3; ++a) {
        const double end = g.origin[a] + n[a] * g.voxelSize;
        EXPECT_LE(g.origin[a], lo[a] - pad + 1e-9);
        EXPECT_GT(g.origin[a] + g.voxelSize, lo[a] - pad);
        EXPECT_GE(end, hi[a] + pad - 1e-9);
        EXPECT_LT(end - g.voxelSize, hi[a] + pad);
        // Dense voxel centres sit on the target's voxel centres (multiples of 0.3).
        const double c = g.centre(a, 0) / 0.3;
        EXPECT_NEAR(c, std::round(c), 1e-9);
    }
}

TEST(VdbTargetFile, DeepInteriorBeyondNarrowBandCountsAsInside) {
    TempDir dir;
    const std::string path = dir.file("big.vdb");
    writeTargetVdb(cubeMesh(3.0f), 0.35, "big.obj", path);  // centre is 8.6 voxels deep; band is 3
    const VolumeTarget t = loadVolumeTarget({{path}});
    const std::uint64_t expected = expectBitsMatchBox(t.fill, t.grid, glm::dvec3(-3), glm::dvec3(3));
    EXPECT_EQ(expected, 17u * 17u * 17u);
    EXPECT_EQ(t.fillCount, expected);
}

TEST(VdbTargetFile, WrittenFileCarriesLevelSetClassNameAndMetadata) {
    TempDir dir;
    const std::string path = dir.file("cube.vdb");
    writeTargetVdb(boxMesh({-1, -2, -3}, {1, 2, 3}), 0.25, "meshes/box.obj", path);
    openvdb::initialize();
    openvdb::io::File file(path);
    file.open();
    const openvdb::GridPtrVecPtr grids = file.getGrids();
    ASSERT_EQ(grids->size(), 1u);
    const openvdb::GridBase::Ptr g = grids->front();
    EXPECT_TRUE(g->isType<openvdb::FloatGrid>());
    EXPECT_EQ(g->getName(), "target");
    EXPECT_EQ(g->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_DOUBLE_EQ(g->metaValue<double>("voxel_size"), 0.25);
    EXPECT_EQ(g->metaValue<openvdb::Vec3d>("bounds_min"), openvdb::Vec3d(-1, -2, -3));
    EXPECT_EQ(g->metaValue<openvdb::Vec3d>("bounds_max"), openvdb::Vec3d(1, 2, 3));
    EXPECT_EQ(g->metaValue<std::string>("source"), "meshes/box.obj");
    EXPECT_EQ(g->metaValue<std::string>("shapevo_role"), "fill");
}

TEST(VdbTargetFile, RefusesToOverwriteUnlessAskedAndLeavesNoTemporaryFiles) {
    TempDir dir;
    const std::string path = writeFile(dir, "cube.vdb", "precious");
    try {
        writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", path);
        ADD_FAILURE() << "overwrote an existing file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    std::ifstream in(path);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "precious");

    writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", path, /*overwrite=*/true);
    EXPECT_EQ(loadVolumeTarget({{path}}).fillCount, 343u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1) << "temporary file left";
}

TEST(VdbTargetFile, WriteRejectsBadVoxelSizeEmptyMeshAndMissingDirectory) {
    TempDir dir;
    EXPECT_THROW(writeTargetVdb(cubeMesh(1.0f), 0.0, "cube.obj", dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeTargetVdb(cubeMesh(1.0f), -0.1, "cube.obj", dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeTargetVdb(cubeMesh(1.0f), std::nan(""), "cube.obj", dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeTargetVdb(cubeMesh(1000.0f), 1e-3, "cube.obj", dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeTargetVdb(Mesh{}, 0.1, "empty.obj", dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", dir.file("no/such/dir/a.vdb")), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.vdb")));
}

TEST(VdbTargetFile, LoadingNonVdbFileFailsNamingIt) {
    TempDir dir;
    const std::string path = writeFile(dir, "notes.vdb", "this is not a VDB file\n");
    try {
        loadVolumeTarget({{path}});
        ADD_FAILURE() << "accepted a text file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    const std::string missing = dir.file("missing.vdb");
    try {
        loadVolumeTarget({{missing}});
        ADD_FAILURE() << "accepted a missing file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
}

TEST(VdbTargetFile, LoadingVdbWithoutUsableFloatGridFailsNamingIt) {
    TempDir dir;
    openvdb::initialize();
    const std::string ints = dir.file("ints.vdb");
    openvdb::Int32Grid::Ptr intGrid = openvdb::Int32Grid::create(0);
    intGrid->tree().setValue(openvdb::Coord(1, 2, 3), 7);
    openvdb::io::File(ints).write({intGrid});
    try {
        loadVolumeTarget({{ints}});
        ADD_FAILURE() << "accepted a file without float grids";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(ints), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no float grid"), std::string::npos) << e.what();
    }
    const std::string empty = dir.file("empty.vdb");
    openvdb::io::File(empty).write({openvdb::FloatGrid::create(1.0f)});
    try {
        loadVolumeTarget({{empty}});
        ADD_FAILURE() << "accepted an empty grid";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(empty), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
}

TEST(VdbTargetFile, AvoidTargetsSetAvoidBitsOnly) {
    TempDir dir;
    const std::string fill = dir.file("fill.vdb"), avoid = dir.file("avoid.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.3, "fill.obj", fill);
    writeTargetVdb(boxMesh(glm::vec3(1.35f), glm::vec3(2.05f)), 0.3, "avoid.obj", avoid);
    const VolumeTarget t = loadVolumeTarget({{fill}, {avoid, /*avoid=*/true}});
    EXPECT_EQ(expectBitsMatchBox(t.fill, t.grid, glm::dvec3(-1), glm::dvec3(1)), 343u);
    EXPECT_EQ(expectBitsMatchBox(t.avoid, t.grid, glm::dvec3(1.35f), glm::dvec3(2.05f)), 8u);
    EXPECT_EQ(t.fillCount, 343u);
    EXPECT_EQ(t.avoidCount, 8u);

    const VolumeTarget fillOnly = loadVolumeTarget({{fill}});
    EXPECT_EQ(fillOnly.avoidCount, 0u);
    EXPECT_NE(fillOnly.hash, t.hash);
    EXPECT_EQ(loadVolumeTarget({{fill}, {avoid, true}}).hash, t.hash) << "hash must be deterministic";
}

TEST(VdbTargetFile, OverrideGridIsUsedExactly) {
    TempDir dir;
    const std::string path = dir.file("cube.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", path);
    // On the target's lattice (corners at odd multiples of 0.15), but its own extent.
    const GridOverride box{glm::dvec3(-1.65, -1.65, -0.75), glm::dvec3(1.75, 1.65, 0.75), 0.3};
    const VolumeTarget t = loadVolumeTarget({{path}}, &box);
    EXPECT_EQ(t.grid.origin, box.min);
    EXPECT_EQ(t.grid.nx, 12);  // ceil(3.4 / 0.3)
    EXPECT_EQ(t.grid.ny, 11);
    EXPECT_EQ(t.grid.nz, 5);
    EXPECT_EQ(t.grid.voxelSize, 0.3);
    EXPECT_EQ(expectBitsMatchBox(t.fill, t.grid, glm::dvec3(-1), glm::dvec3(1)), 7u * 7u * 5u);
    EXPECT_EQ(t.fillCount, 7u * 7u * 5u);
}

TEST(VdbTargetFile, OverrideGridOffTheTargetLatticeApproximatesTheVolume) {
    TempDir dir;
    const std::string path = dir.file("cube.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.1, "cube.obj", path);
    const GridOverride box{glm::dvec3(-1.31), glm::dvec3(1.4), 0.07};
    const VolumeTarget t = loadVolumeTarget({{path}}, &box);
    const double volume = double(t.fillCount) * std::pow(box.voxelSize, 3);
    EXPECT_NEAR(volume, 8.0, 8.0 * 0.05);
}

TEST(VdbTargetFile, UnusableOverrideGridIsRejected) {
    TempDir dir;
    const std::string path = dir.file("cube.vdb");
    writeTargetVdb(cubeMesh(1.0f), 0.3, "cube.obj", path);
    const GridOverride zeroVoxel{glm::dvec3(-1), glm::dvec3(1), 0.0};
    EXPECT_THROW(loadVolumeTarget({{path}}, &zeroVoxel), InputError);
    const GridOverride inverted{glm::dvec3(1), glm::dvec3(-1), 0.1};
    EXPECT_THROW(loadVolumeTarget({{path}}, &inverted), InputError);
    const GridOverride huge{glm::dvec3(-1000), glm::dvec3(1000), 1e-3};
    EXPECT_THROW(loadVolumeTarget({{path}}, &huge), InputError);
}

}  // namespace
}  // namespace shapevo
