// Tests for readMesh (OBJ, PLY, STL round trips and every malformed-input error) and requireClosed.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <sstream>

#include "cube_mesh.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::expectInputError;

using test::cubeMesh;
using test::TempDir;
using test::writeFile;

// ---- writers used to produce test files from a Mesh ----

std::string toObj(const Mesh& m) {
    std::ostringstream s;
    s << "# cube\n";
    for (const auto& v : m.vertices) s << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (const auto& t : m.triangles) s << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    return s.str();
}

std::string plyHeader(const Mesh& m, const char* format) {
    std::ostringstream s;
    s << "ply\nformat " << format << " 1.0\ncomment written by a test\nelement vertex " << m.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\n"
      << "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    return s.str();
}

std::string toPlyAscii(const Mesh& m) {
    std::ostringstream s;
    s << plyHeader(m, "ascii");
    for (const auto& v : m.vertices) s << v.x << ' ' << v.y << ' ' << v.z << " 255\n";
    for (const auto& t : m.triangles) s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    s << "0 1\n";
    return s.str();
}

template <class T>
void putLE(std::string& out, T value) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));  // the test machine is little-endian (x86-64/arm64)
    out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

std::string toPlyBinary(const Mesh& m) {
    std::string s = plyHeader(m, "binary_little_endian");
    for (const auto& v : m.vertices) {
        putLE(s, v.x), putLE(s, v.y), putLE(s, v.z);
        putLE(s, std::uint8_t(255));
    }
    for (const auto& t : m.triangles) {
        putLE(s, std::uint8_t(3));
        for (auto i : t) putLE(s, std::int32_t(i));
    }
    putLE(s, std::int32_t(0)), putLE(s, std::int32_t(1));
    return s;
}

std::string toStlAscii(const Mesh& m) {
    std::ostringstream s;
    s << "solid cube\n";
    for (const auto& t : m.triangles) {
        s << "  facet normal 0 0 0\n    outer loop\n";
        for (auto i : t) s << "      vertex " << m.vertices[i].x << ' ' << m.vertices[i].y << ' ' << m.vertices[i].z << '\n';
        s << "    endloop\n  endfacet\n";
    }
    s << "endsolid cube\n";
    return s.str();
}

std::string toStlBinary(const Mesh& m) {
    std::string s(80, ' ');
    s.replace(0, 10, "solid cube");  // binary files may start with "solid" too
    putLE(s, std::uint32_t(m.triangles.size()));
    for (const auto& t : m.triangles) {
        for (int k = 0; k < 3; ++k) putLE(s, 0.0f);
        for (auto i : t) putLE(s, m.vertices[i].x), putLE(s, m.vertices[i].y), putLE(s, m.vertices[i].z);
        putLE(s, std::uint16_t(0));
    }
    return s;
}

// ---- comparisons ----

void expectSameIndexedMesh(const Mesh& expected, const Mesh& actual) {
    ASSERT_EQ(expected.vertices.size(), actual.vertices.size());
    for (std::size_t i = 0; i < expected.vertices.size(); ++i) EXPECT_EQ(expected.vertices[i], actual.vertices[i]) << i;
    EXPECT_EQ(expected.triangles, actual.triangles);
}

/// STL has no indices: compare each triangle's corner positions, in order.
void expectSameTriangleGeometry(const Mesh& expected, const Mesh& actual) {
    ASSERT_EQ(expected.triangles.size(), actual.triangles.size());
    for (std::size_t t = 0; t < expected.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(expected.vertices[expected.triangles[t][k]], actual.vertices[actual.triangles[t][k]]) << t;
}


// ---- round trips ----

TEST(MeshReader, ObjRoundTripKeepsCubeVerticesAndTriangles) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    expectSameIndexedMesh(cube, readMesh(writeFile(dir, "cube.obj", toObj(cube))));
}

TEST(MeshReader, ObjQuadsWithSlashFormsAndNegativeIndicesAreFanTriangulated) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    std::ostringstream s;
    s << "mtllib cube.mtl\no cube\r\n";
    for (const auto& v : cube.vertices) s << "v " << v.x << ' ' << v.y << ' ' << v.z << " 1.0\r\n";
    s << "vt 0 0\nvn 0 0 1\ns off\nusemtl none\n";
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    const char* forms[6] = {"%", "%/1", "%/1/1", "%//1", "-", "-/1/1"};  // '-': negative index
    for (int f = 0; f < 6; ++f) {
        s << "f";
        for (auto q : quads[f]) {
            std::string form = forms[f];
            const std::string index = form[0] == '-' ? std::to_string(int(q) - 8) : std::to_string(q + 1);
            form.replace(0, 1, index);
            s << ' ' << form;
        }
        s << "  # a quad\n";
    }
    expectSameIndexedMesh(cube, readMesh(writeFile(dir, "quads.obj", s.str())));
}

TEST(MeshReader, PlyAsciiRoundTripSkipsExtraPropertiesAndElements) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    expectSameIndexedMesh(cube, readMesh(writeFile(dir, "cube.ply", toPlyAscii(cube))));
}

TEST(MeshReader, PlyBinaryLittleEndianRoundTrip) {
    TempDir dir;
    const Mesh cube = cubeMesh(0.75f);
    expectSameIndexedMesh(cube, readMesh(writeFile(dir, "cube.PLY", toPlyBinary(cube))));
}

TEST(MeshReader, StlAsciiRoundTripWeldsEqualPositions) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    const Mesh read = readMesh(writeFile(dir, "cube.stl", toStlAscii(cube)));
    EXPECT_EQ(read.vertices.size(), 8u);
    expectSameTriangleGeometry(cube, read);
}

TEST(MeshReader, StlBinaryRoundTripEvenWhenHeaderSaysSolid) {
    TempDir dir;
    const Mesh cube = cubeMesh(0.5f);
    const Mesh read = readMesh(writeFile(dir, "cube.stl", toStlBinary(cube)));
    EXPECT_EQ(read.vertices.size(), 8u);
    expectSameTriangleGeometry(cube, read);
}

// ---- errors: each names the file and, for text formats, the line ----

TEST(MeshReaderErrors, MissingFileNamesThePath) {
    TempDir dir;
    const std::string path = dir.file("absent.obj");
    expectInputError([&] { readMesh(path); }, {path, "cannot open"});
}

TEST(MeshReaderErrors, UnknownExtensionIsRejected) {
    TempDir dir;
    const std::string path = writeFile(dir, "cube.xyz", "OFF\n");
    expectInputError([&] { readMesh(path); }, {path, ".xyz"});
}

TEST(MeshReaderErrors, ObjMalformedNumberNamesFileAndLine) {
    TempDir dir;
    const std::string path = writeFile(dir, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1.5x 0\nf 1 2 3\n");
    expectInputError([&] { readMesh(path); }, {path + ":3:", "malformed number '1.5x'"});
}

TEST(MeshReaderErrors, ObjFaceIndexOutOfRangeNamesFileAndLine) {
    TempDir dir;
    const std::string path = writeFile(dir, "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    expectInputError([&] { readMesh(path); }, {path + ":5:", "out of range"});
    const std::string zero = writeFile(dir, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    expectInputError([&] { readMesh(zero); }, {zero + ":4:", "out of range"});
    const std::string negative = writeFile(dir, "negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    expectInputError([&] { readMesh(negative); }, {negative + ":4:", "out of range"});
}

TEST(MeshReaderErrors, ObjFaceWithTwoVerticesNamesFileAndLine) {
    TempDir dir;
    const std::string path = writeFile(dir, "two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2\n");
    expectInputError([&] { readMesh(path); }, {path + ":5:", "at least 3"});
}

TEST(MeshReaderErrors, ObjNonFiniteCoordinateNamesFileAndLine) {
    TempDir dir;
    for (const char* value : {"nan", "inf", "-inf", "1e39"}) {
        const std::string path = writeFile(dir, "nonfinite.obj", std::string("v 0 0 0\nv 1 ") + value + " 0\n");
        expectInputError([&] { readMesh(path); }, {path + ":2:", "non-finite"});
    }
}

TEST(MeshReaderErrors, MeshWithoutTrianglesIsRejected) {
    TempDir dir;
    const std::string path = writeFile(dir, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    expectInputError([&] { readMesh(path); }, {path, "no triangles"});
    const std::string empty = writeFile(dir, "empty.stl", "");
    expectInputError([&] { readMesh(empty); }, {empty});
}

TEST(MeshReaderErrors, PlyAsciiErrorsNameFileAndLine) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    std::string text = toPlyAscii(cube);
    // Header has 14 lines, then 8 vertex lines; the first face is line 23.
    std::string badIndex = text;
    badIndex.replace(badIndex.find("\n3 ") + 1, 7, "3 0 1 8");
    const std::string p1 = writeFile(dir, "index.ply", badIndex);
    expectInputError([&] { readMesh(p1); }, {p1 + ":23:", "out of range"});

    std::string badNumber = text;
    badNumber.replace(badNumber.find("end_header\n") + 11, 2, "x1");
    const std::string p2 = writeFile(dir, "number.ply", badNumber);
    expectInputError([&] { readMesh(p2); }, {p2 + ":15:", "malformed number"});

    std::string twoCorners = text;
    twoCorners.replace(twoCorners.find("\n3 ") + 1, 1, "2");
    const std::string p3 = writeFile(dir, "two.ply", twoCorners);
    expectInputError([&] { readMesh(p3); }, {p3 + ":23:", "at least 3"});
}

TEST(MeshReaderErrors, PlyBinaryTruncatedAndBigEndianAreRejected) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    const std::string bytes = toPlyBinary(cube);
    const std::string p1 = writeFile(dir, "short.ply", bytes.substr(0, bytes.size() - 20));
    expectInputError([&] { readMesh(p1); }, {p1 + ":face 11", "unexpected end of file"});
    std::string big = bytes;
    big.replace(big.find("binary_little_endian"), 20, "binary_big_endian");
    const std::string p2 = writeFile(dir, "big.ply", big);
    expectInputError([&] { readMesh(p2); }, {p2 + ":2:", "binary_big_endian"});
}

TEST(MeshReaderErrors, StlFacetWithTwoVerticesNamesFileAndLine) {
    TempDir dir;
    const std::string path = writeFile(dir, "two.stl",
                                       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                       "endloop\nendfacet\nendsolid x\n");
    expectInputError([&] { readMesh(path); }, {path + ":6:", "at least 3"});
}

TEST(MeshReaderErrors, StlMalformedNumberAndNonFiniteAreRejected) {
    TempDir dir;
    const std::string p1 = writeFile(dir, "num.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                "vertex 1 0 0\nvertex 0 one 0\nendloop\nendfacet\nendsolid x\n");
    expectInputError([&] { readMesh(p1); }, {p1 + ":6:", "malformed number 'one'"});
    Mesh cube = cubeMesh(1.0f);
    cube.vertices[7].y = std::numeric_limits<float>::infinity();
    const std::string p2 = writeFile(dir, "inf.stl", toStlBinary(cube));
    expectInputError([&] { readMesh(p2); }, {p2 + ":triangle 2", "non-finite"});
}

TEST(MeshReaderErrors, StlBinaryTruncatedIsRejected) {
    TempDir dir;
    const std::string bytes = toStlBinary(cubeMesh(1.0f));
    std::string shortened = bytes.substr(0, bytes.size() - 10);
    shortened.replace(0, 5, "STLB ");  // not "solid", so it must be binary
    const std::string path = writeFile(dir, "short.stl", shortened);
    expectInputError([&] { readMesh(path); }, {path, "truncated"});
}

// ---- closedness ----

TEST(RequireClosed, ClosedCubePasses) { EXPECT_NO_THROW(requireClosed(cubeMesh(1.0f), "cube.obj")); }

TEST(RequireClosed, SeamWithDuplicatedVerticesStillCountsAsClosed) {
    Mesh cube = cubeMesh(1.0f);
    cube.vertices.push_back(cube.vertices[0]);  // a UV-seam style copy of vertex 0
    cube.triangles[0][0] = 8;
    EXPECT_NO_THROW(requireClosed(cube, "cube.obj"));
}

TEST(RequireClosed, CubeWithMissingTriangleIsRejectedWithEdgeCountAndExample) {
    Mesh cube = cubeMesh(1.0f);
    cube.triangles.pop_back();
    expectInputError([&] { requireClosed(cube, "open.obj"); }, {"open.obj", "not closed", "3 edges", "(-1, -1, 1) - (-1, 1, 1)"});
}

TEST(RequireClosed, EdgeSharedByThreeTrianglesIsRejected) {
    Mesh cube = cubeMesh(1.0f);
    cube.triangles.push_back(cube.triangles[0]);  // duplicate face: its edges are used 3 or 4 times
    expectInputError([&] { requireClosed(cube, "fin.obj"); }, {"fin.obj", "not closed"});
}

TEST(MeshReaderErrors, PlyListLengthMustBeAWholeNumber) {  // found by fuzz_ply_reader
    TempDir dir;
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list float int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    for (const char* count : {"1e30", "nan", "3.5", "-1"}) {
        const std::string path = writeFile(dir, std::string("count-") + count + ".ply", head + count + " 0 1 2\n");
        expectInputError([&] { readMesh(path); }, {path + ":13:", "list length"});
    }
}

TEST(MeshShapeFile, AMeshFarFromTheOriginKeepsItsShape) {  // (lo + hi) / 2 overflowed to infinity
    TempDir dir;
    const std::string path = writeFile(dir, "far.obj", "v 3e38 0 0\nv 3.4e38 0 0\nv 3e38 1 0\nv 3e38 0 1\n"
                                                       "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const MeshShape shape = loadMeshShape(path);
    float lo = 1, hi = -1;
    for (const glm::vec3& v : shape.vertices) lo = std::min(lo, v.x), hi = std::max(hi, v.x);
    EXPECT_EQ(lo, -1.0f);
    EXPECT_EQ(hi, 1.0f) << "the two x values stay apart";
}

}  // namespace
}  // namespace shapevo
