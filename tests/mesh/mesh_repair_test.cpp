// Tests for analyseMesh (exact defect counts on meshes built with known seams, holes, doubled,
// degenerate and non-manifold triangles) and repairForVolume (closed meshes pass unchanged,
// holes are filled until every edge is shared, a mostly-open mesh is refused) and its report.
#include <gtest/gtest.h>

#include <string>

#include "../mesh/cube_mesh.hpp"
#include "../mesh/imperfect_meshes.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_defects.hpp"
#include "mesh/mesh_repair.hpp"

namespace shapevo {
namespace {

using namespace test;

TEST(MeshDefects, ClosedCubeHasNone) {
    const MeshDefects d = analyseMesh(cubeMesh(1.0f));
    EXPECT_TRUE(d.closed());
    EXPECT_EQ(d.triangles, 12u);
    EXPECT_EQ(d.openEdges + d.holes + d.nonManifoldEdges + d.duplicateTriangles + d.degenerateTriangles + d.seamVertices, 0u);
    EXPECT_EQ(d.components, 1u);
    EXPECT_NEAR(d.surfaceArea, 24.0, 1e-9);
}

TEST(MeshDefects, SphereSeamIsWeldedAndClosed) {
    const Mesh sphere = seamSphere(1.0f, 8, 12);
    const MeshDefects d = analyseMesh(sphere);
    EXPECT_TRUE(d.closed());
    // 9 x 13 vertices for 8 x 12 + 2 distinct positions: the seam column and the poles repeat.
    EXPECT_EQ(d.seamVertices, 9u * 13u - (7u * 12u + 2u));
}

TEST(MeshDefects, RemovedTrianglesAreCountedAsOpenEdgesAndHoles) {
    const Mesh cube = gridCube(1.0f, 4);  // 6 * 32 triangles
    // Triangles 0 and 1 form one quad (one hole of 4 edges); 40 is alone on another face (3 edges).
    const MeshDefects d = analyseMesh(withoutTriangles(cube, {0, 1, 40}));
    EXPECT_EQ(d.openEdges, 7u);
    EXPECT_EQ(d.holes, 2u);
    EXPECT_EQ(d.nonManifoldEdges, 0u);
}

TEST(MeshDefects, DoubledDegenerateAndNonManifoldTrianglesAreCounted) {
    Mesh cube = cubeMesh(1.0f);
    cube.triangles.push_back(cube.triangles[3]);                                            // doubled
    cube.triangles.push_back({cube.triangles[5][2], cube.triangles[5][1], cube.triangles[5][0]});  // doubled, reversed
    cube.triangles.push_back({0, 0, 1});                                                    // collapsed
    const MeshDefects d = analyseMesh(cube);
    EXPECT_EQ(d.duplicateTriangles, 2u);
    EXPECT_EQ(d.degenerateTriangles, 1u);
    EXPECT_TRUE(d.closed());
    EXPECT_EQ(d.nonManifoldEdges, 0u);

    // Two cubes touching along one edge (x = y = 0): that edge has four triangles.
    const Mesh pair = joined(boxMesh({0, 0, 0}, {1, 1, 1}), boxMesh({-1, -1, 0}, {0, 0, 1}));
    const MeshDefects p = analyseMesh(pair);
    EXPECT_TRUE(p.closed());
    EXPECT_EQ(p.nonManifoldEdges, 1u);
    EXPECT_EQ(p.seamVertices, 2u);
    EXPECT_EQ(p.components, 1u);
}

TEST(MeshRepair, ClosedMeshPassesUnchangedAndIsReportedClosed) {
    const Mesh cube = cubeMesh(1.0f);
    const MeshRepair r = repairForVolume(cube, "cube.obj");
    EXPECT_EQ(r.mesh.vertices, cube.vertices);
    EXPECT_EQ(r.mesh.triangles, cube.triangles);
    EXPECT_EQ(r.addedTriangles, 0u);
    EXPECT_EQ(describeRepair(r), "12 triangles, closed");
}

TEST(MeshRepair, HolesAreFilledUntilEveryEdgeIsSharedByTwoTriangles) {
    // Four holes apart: a quad at a corner, a lone triangle, a quad, a lone triangle.
    const Mesh holed = withoutTriangles(gridCube(1.0f, 4), {0, 1, 40, 100, 101, 170});
    const MeshRepair r = repairForVolume(holed, "holed.obj");
    EXPECT_EQ(r.found.openEdges, 14u);
    EXPECT_EQ(r.found.holes, 4u);
    EXPECT_EQ(r.filledHoles, 4u);
    EXPECT_EQ(r.unfilledHoles, 0u);
    EXPECT_EQ(r.addedTriangles, 6u);
    const MeshDefects after = analyseMesh(r.mesh);
    EXPECT_TRUE(after.closed()) << after.openEdges << " open edges left";
    EXPECT_EQ(after.nonManifoldEdges, 0u);
    EXPECT_NEAR(after.surfaceArea, 24.0, 1e-4);  // the holes were flat: the fill restores the faces
    EXPECT_EQ(describeRepair(r), "186 triangles, 14 open edges in 4 holes: filled (6 triangles added)");
}

TEST(MeshRepair, HolesTouchingAtAVertexAreCountedApartAndClosed) {
    // The quad of triangles 100, 101 and triangle 150 share the cube-edge vertex (0.5, 1, -1).
    const Mesh holed = withoutTriangles(gridCube(1.0f, 4), {100, 101, 150});
    const MeshRepair r = repairForVolume(holed, "touching.obj");
    EXPECT_EQ(r.found.openEdges, 7u);
    EXPECT_EQ(r.found.holes, 2u);
    const MeshDefects after = analyseMesh(r.mesh);
    EXPECT_EQ(r.filledHoles, 2u);  // one figure-8 border cycle, split at the shared vertex
    EXPECT_EQ(r.addedTriangles, 3u);
    EXPECT_TRUE(after.closed()) << after.openEdges << " open edges left";
    EXPECT_EQ(after.nonManifoldEdges, 0u);
    EXPECT_NEAR(after.surfaceArea, 24.0, 1e-4);
}

TEST(MeshRepair, AnOpenSheetIsRefusedAsMostlyHoles) {
    Mesh sheet;
    sheet.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
    try {
        repairForVolume(sheet, "sheet.obj");
        ADD_FAILURE() << "an open sheet was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("sheet.obj: ", 0), 0u) << what;
        EXPECT_NE(what.find("cannot be determined"), std::string::npos) << what;
        EXPECT_NE(what.find("mostly holes"), std::string::npos) << what;
    }
}

TEST(MeshRepair, ReportGroupsThousands) {
    EXPECT_EQ(groupedNumber(0), "0");
    EXPECT_EQ(groupedNumber(999), "999");
    EXPECT_EQ(groupedNumber(1000), "1,000");
    EXPECT_EQ(groupedNumber(12345678), "12,345,678");
}

}  // namespace
}  // namespace shapevo
