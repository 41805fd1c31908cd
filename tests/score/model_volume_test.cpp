// Model volume: the written VDB holds exactly the voxels the Voxelizer covers (count and
// positions), as a fog volume with value 1, placed in world space like the dense grid, with
// shapevo's metadata; bad grids and unwritable paths throw.
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "base/input_error.hpp"
#include "score/volume/model_volume.hpp"
#include "score/volume/voxelizer.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace model_volume_test {  // named: a unity batch may hold another testGrid()

GridSpec testGrid() {
    GridSpec g;
    g.origin = {-1.0, 0.5, 2.0};
    g.voxelSize = 0.25;
    g.nx = 70;  // more than one 64-bit word per row
    g.ny = 30;
    g.nz = 20;
    return g;
}

Primitive box(const glm::vec3& centre, const glm::vec3& half, const glm::mat3& axes = glm::mat3(1.0f)) {
    Primitive p;
    p.centre = centre;
    p.half = half;
    p.axes = axes;
    return p;
}

/// Boxes only (the Voxelizer's own kind): axis-aligned, rotated, overlapping, partly off the grid.
Geometry testModel() {
    Geometry g;
    const glm::vec3 lo(-1.0f, 0.5f, 2.0f);
    g.primitives.push_back(box(lo + glm::vec3(4.0f, 3.0f, 2.5f), {2.0f, 1.0f, 0.8f}));
    g.primitives.push_back(box(lo + glm::vec3(5.0f, 4.0f, 2.5f), {1.0f, 1.5f, 1.0f}));
    g.primitives.push_back(
        box(lo + glm::vec3(12.0f, 4.0f, 3.0f), {1.2f, 0.6f, 1.5f},
            glm::mat3(glm::rotate(glm::mat4(1.0f), 0.6f, glm::normalize(glm::vec3(1.0f, 1.0f, 0.3f))))));
    g.primitives.push_back(box(lo + glm::vec3(17.4f, 7.0f, 4.9f), {1.0f, 1.0f, 1.0f}));  // crosses the grid's edge
    return g;
}

/// Bit rows of `model` as the Voxelizer leaves them after add().
std::vector<std::uint64_t> occupancy(const Geometry& model, const GridSpec& grid) {
    Voxelizer v(grid);
    VoxelCounts counts;
    for (const Primitive& p : model.primitives) v.add(p, model.meshes, counts);
    return v.occupancy();
}

openvdb::FloatGrid::Ptr readDensity(const std::string& path) {
    openvdb::initialize();
    openvdb::io::File file(path);
    file.open();
    openvdb::GridBase::Ptr base = file.readGrid("density");
    file.close();
    return openvdb::gridPtrCast<openvdb::FloatGrid>(base);
}

TEST(ModelVolume, ActiveVoxelsAreExactlyTheVoxelizersBitsAtTheGridsWorldPositions) {
    test::TempDir dir;
    const GridSpec grid = testGrid();
    const Geometry model = testModel();
    const std::vector<std::uint64_t> bits = occupancy(model, grid);
    std::uint64_t occupied = 0;
    for (std::uint64_t w : bits) occupied += std::uint64_t(std::popcount(w));
    ASSERT_GT(occupied, 500u);

    const std::string path = dir.file("best.vdb");
    writeModelVdb(model, grid, path);
    const openvdb::FloatGrid::Ptr vdb = readDensity(path);
    ASSERT_TRUE(vdb);
    EXPECT_EQ(vdb->activeVoxelCount(), occupied);
    EXPECT_EQ(vdb->getGridClass(), openvdb::GRID_FOG_VOLUME);
    EXPECT_EQ(vdb->background(), 0.0f);
    EXPECT_EQ(vdb->metaValue<std::string>("source"), "shapevo model");
    EXPECT_EQ(vdb->metaValue<double>("voxel_size"), 0.25);
    EXPECT_EQ(vdb->metaValue<openvdb::Int64>("primitives"), 4);
    std::uint64_t matched = 0;
    for (auto it = vdb->cbeginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        EXPECT_EQ(*it, 1.0f);
        ASSERT_TRUE(c.x() >= 0 && c.x() < grid.nx && c.y() >= 0 && c.y() < grid.ny && c.z() >= 0 && c.z() < grid.nz);
        const std::size_t row = (std::size_t(c.z()) * std::size_t(grid.ny) + std::size_t(c.y())) * std::size_t(grid.wordsPerRow());
        matched += (bits[row + std::size_t(c.x() >> 6)] >> (c.x() & 63)) & 1u;
        const openvdb::Vec3d world = vdb->indexToWorld(c);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(world[a], grid.centre(a, c[a]), 1e-9);
    }
    EXPECT_EQ(matched, occupied) << "every active voxel is a covered voxel";
}

TEST(ModelVolume, EmptyModelWritesAnEmptyGridAndReplacesAnOldFile) {
    test::TempDir dir;
    const std::string path = dir.file("best.vdb");
    writeModelVdb(testModel(), testGrid(), path);
    writeModelVdb(Geometry{}, testGrid(), path);
    const openvdb::FloatGrid::Ptr vdb = readDensity(path);
    ASSERT_TRUE(vdb);
    EXPECT_EQ(vdb->activeVoxelCount(), 0u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1) << "no temporary left";
}

TEST(ModelVolume, EmptyGridOrUnwritablePathThrowsInputError) {
    test::TempDir dir;
    GridSpec empty = testGrid();
    empty.ny = 0;
    EXPECT_THROW(writeModelVdb(testModel(), empty, dir.file("a.vdb")), InputError);
    EXPECT_THROW(writeModelVdb(testModel(), testGrid(), dir.file("no/dir/a.vdb")), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace model_volume_test
}  // namespace shapevo
