// fittingVoxelSize (issue 40, item 2): without --voxel-size, `shapevo target` makes the mesh's
// longest side 128 voxels, the size rounded to 3 significant digits; vertices no triangle uses
// do not count; a mesh without extent gets 0 (which writeTargetVdb refuses).
#include <gtest/gtest.h>

#include "../mesh/cube_mesh.hpp"
#include "run/target_from_mesh.hpp"

namespace shapevo {
namespace {

TEST(FittingVoxelSize, TheLongestSideIs128VoxelsRoundedTo3SignificantDigits) {
    EXPECT_EQ(kVoxelsAlongLongestSide, 128);
    EXPECT_DOUBLE_EQ(fittingVoxelSize(test::boxMesh({0, 0, 0}, {1, 3, 2})), 0.0234);         // 3 / 128 = 0.0234375
    EXPECT_DOUBLE_EQ(fittingVoxelSize(test::boxMesh({0, 0, 0}, {250, 180, 60})), 1.95);      // 1.953125: centimetres
    EXPECT_DOUBLE_EQ(fittingVoxelSize(test::boxMesh({-1288, 0, 0}, {1289, 40, 9})), 20.1);  // 2577 / 128 = 20.13...
    EXPECT_DOUBLE_EQ(fittingVoxelSize(test::boxMesh({0, 0, 0}, {12800, 1, 1})), 100.0);
    EXPECT_DOUBLE_EQ(fittingVoxelSize(test::boxMesh({0, 0, 0}, {0.001f, 0.0005f, 0.0001f})), 7.81e-6);
}

TEST(FittingVoxelSize, OnlyTheTrianglesCornersCount) {
    Mesh m = test::cubeMesh(1.0f);  // 2 across: 2 / 128 = 0.015625
    m.vertices.push_back({1000.0f, 0.0f, 0.0f});
    EXPECT_DOUBLE_EQ(fittingVoxelSize(m), 0.0156);
}

TEST(FittingVoxelSize, AMeshWithoutExtentGetsZero) {
    Mesh m;
    EXPECT_EQ(fittingVoxelSize(m), 0.0);
    m.vertices = {{1, 1, 1}};
    m.triangles = {{0, 0, 0}};
    EXPECT_EQ(fittingVoxelSize(m), 0.0);
}

}  // namespace
}  // namespace shapevo
