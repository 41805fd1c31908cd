// `shapevo target` on degenerate meshes (issue 40, item 3), through the real binary: a mesh with
// no valid face (OBJ, STL), a face whose vertex index is out of range (the measured case: an OFF
// file Assimp reads on past, clamping the index; and an OBJ), and a mesh enclosing no volume (a
// closed but flat mesh; a closed surface of zero thickness through voxel centres) each exit 2
// with one message naming the file and what is wrong, and the -o file is not created.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::runShapevo;
using test::TempDir;
using test::writeFile;

/// Runs `shapevo target FILE -o out.vdb` (with `flags`) on `text` written to `dir`/`name`;
/// expects exit 2, one error naming the file with `what`, and no out.vdb.
void expectRefusedMesh(const std::string& name, const std::string& text, const std::string& what, const std::string& flags = "") {
    TempDir dir;
    const std::string mesh = dir.file(name);
    writeFile(mesh, text);
    const auto r = runShapevo("target " + mesh + " -o " + dir.file("out.vdb") + flags);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + mesh + ":"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("wrote"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.vdb"))) << name;
}

/// A closed surface of `quads` (each 4 corner indices into `vertices`), every quad twice: once
/// split along one diagonal, once (reversed) along the other, so every edge has two triangles
/// and yet the surface is of zero thickness.
std::string doubleSidedObj(const std::string& vertices, const std::vector<std::array<int, 4>>& quads) {
    std::string obj = vertices;
    for (const auto& q : quads) {
        obj += "f " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + "\n";
        obj += "f " + std::to_string(q[0]) + " " + std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
        obj += "f " + std::to_string(q[0]) + " " + std::to_string(q[3]) + " " + std::to_string(q[1]) + "\n";
        obj += "f " + std::to_string(q[1]) + " " + std::to_string(q[3]) + " " + std::to_string(q[2]) + "\n";
    }
    return obj;
}

TEST(TargetDegenerateCli, AnObjWhoseFacesAreAllDegenerateHasNoValidFace) {
    // One triangle on a line, one with a repeated corner, one with two corners at one position.
    expectRefusedMesh("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 0 0\nf 1 2 3\nf 1 1 2\nf 2 4 3\n",
                      "mesh has no valid face: all 3 triangles are degenerate");
}

TEST(TargetDegenerateCli, AnStlWhoseFacetsAreAllDegenerateHasNoValidFace) {
    expectRefusedMesh("dot.stl",
                      "solid dot\nfacet normal 0 0 1\nouter loop\nvertex 1 1 1\nvertex 1 1 1\nvertex 1 1 1\nendloop\nendfacet\n"
                      "endsolid dot\n",
                      "mesh has no valid face: its only triangle is degenerate");
}

TEST(TargetDegenerateCli, TheMalformedOffOfTheIssueIsRefusedNotMadeAOneVoxelTarget) {
    // 3 vertices, then faces whose indices are out of range: Assimp clamps them to the last
    // vertex and reads on; such a file became "inside: volume 0.011 ... wrote" with exit 0.
    expectRefusedMesh("inv.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 7 9\n3 4 5 6\n",
                      "a face has a vertex index Assimp could not use (Assimp: \"OFF: Vertex index is out of range\")");
}

TEST(TargetDegenerateCli, AnOffWhoseFacesAreAllDegenerateHasNoValidFace) {
    expectRefusedMesh("flat.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n3 2 1 0\n", "mesh has no valid face");
}

TEST(TargetDegenerateCli, AnObjFaceIndexOutOfRangeIsRefused) {
    expectRefusedMesh("far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 9\n", "face index 9 out of range");
}

TEST(TargetDegenerateCli, AClosedFlatMeshEnclosesNoVolume) {
    // A square, both sides: closed (every edge in two triangles), all in the plane z = 0.
    expectRefusedMesh("flat.obj", doubleSidedObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n", {{1, 2, 3, 4}}),
                      "the mesh encloses no volume: all its 4 triangles lie in one plane");
    expectRefusedMesh("flat.obj", doubleSidedObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n", {{1, 2, 3, 4}}),
                      "the mesh encloses no volume", " --voxel-size 0.1");
}

TEST(TargetDegenerateCli, AClosedSurfaceOfZeroThicknessHasAnEmptyInside) {
    // Two squares at a right angle, both sides each (an open book of zero-thickness pages): not
    // flat, closed, and its planes x = 0 and z = 0 pass through voxel centres (value 0 there).
    const std::string book = doubleSidedObj("v 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 0 1 1\nv 0 0 1\n", {{1, 2, 3, 4}, {1, 6, 5, 2}});
    expectRefusedMesh("book.obj", book, "the inside of the mesh comes out empty at voxel size 0.00781");
    expectRefusedMesh("book.obj", book, "the inside of the mesh comes out empty at voxel size 0.25", " --voxel-size 0.25");
}

}  // namespace
}  // namespace shapevo
