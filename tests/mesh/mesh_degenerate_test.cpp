// readMesh refuses degenerate meshes whatever reads them (issue 40, item 3): no valid face (every
// triangle without area) in OBJ, PLY, STL and OFF (Assimp); a face index out of range that Assimp
// reads past (it clamps OFF indices); and every caller of the loader gets it (a grammar's mesh
// shape, loadMeshShape). A mesh with some degenerate triangles beside valid ones is read as before.
#include <gtest/gtest.h>

#include "cube_mesh.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::expectInputError;
using test::TempDir;
using test::writeFile;

TEST(MeshDegenerate, NoValidFaceInAnyFormatNamesTheFile) {
    TempDir dir;
    const std::string obj = writeFile(dir, "line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 3 2 1\n");
    expectInputError([&] { readMesh(obj); }, {obj + ": mesh has no valid face: all 2 triangles are degenerate"});
    const std::string ply = writeFile(dir, "dot.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                      "5 5 5\n5 5 5\n5 5 5\n3 0 1 2\n");
    expectInputError([&] { readMesh(ply); }, {ply + ": mesh has no valid face: its only triangle is degenerate"});
    const std::string stl = writeFile(dir, "line.stl",
                                      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 1\nvertex 2 2 2\n"
                                      "endloop\nendfacet\nendsolid s\n");
    expectInputError([&] { readMesh(stl); }, {stl + ": mesh has no valid face"});
    const std::string off = writeFile(dir, "line.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
    expectInputError([&] { readMesh(off); }, {off + ": mesh has no valid face"});
}

TEST(MeshDegenerate, AnOffIndexOutOfRangeIsRefusedThoughAssimpClampsIt) {
    TempDir dir;
    // A valid tetrahedron but for one index: clamped to vertex 3, the face would be (0, 1, 3).
    const std::string off = writeFile(dir, "tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 40\n");
    expectInputError([&] { readMesh(off); }, {off + ": cannot read OFF mesh: a face has a vertex index Assimp could not use",
                                              "OFF: Vertex index is out of range"});
}

TEST(MeshDegenerate, SomeDegenerateTrianglesBesideValidOnesAreReadAsBefore) {
    TempDir dir;
    const std::string obj = writeFile(dir, "tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 1 2\n");
    const Mesh m = readMesh(obj);
    EXPECT_EQ(m.triangles.size(), 5u);
    EXPECT_TRUE(m.warnings.empty());
}

TEST(MeshDegenerate, AGrammarsMeshShapeGetsTheSameCheck) {
    TempDir dir;
    // Closed (every edge in two triangles) but every triangle on one line.
    const std::string obj = writeFile(dir, "leaf.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 3 2 1\n");
    expectInputError([&] { loadMeshShape(obj); }, {obj + ": mesh has no valid face"});
}

}  // namespace
}  // namespace shapevo
