// Tests for readMesh's Assimp formats (OFF, glTF with embedded and external buffers, GLB, DAE,
// 3MF: the source cube's triangles, volume and bounds come back, in world space), its guards
// against bad and hostile files (each one InputError naming the file), the PLY reader's
// stray-header-line warning, and the sandbox Assimp runs in.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <functional>
#include <random>
#include <thread>

#include "cube_mesh.hpp"
#include "mesh_files.hpp"
#include "base/input_error.hpp"
#include "mesh/glb_writer.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "mesh/sandboxed_call.hpp"
#include "../child_processes.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::expectInputError;

using test::cubeMesh;
using test::TempDir;
using test::writeFile;


/// The read mesh is the cube of half size `h` moved by `move`: 12 triangles, closed, outward
/// (volume (2h)^3 > 0), the same bounds.
void expectCube(const Mesh& read, float h, const glm::vec3& move, const std::string& path) {
    EXPECT_EQ(read.triangles.size(), 12u) << path;
    EXPECT_NO_THROW(requireClosed(read, path));
    EXPECT_NEAR(test::signedVolume(read), 8.0 * h * h * h, 1e-4) << path;
    const test::Bounds b = test::bounds(read);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.lo[a], move[a] - h, 1e-5) << path << " axis " << a;
        EXPECT_NEAR(b.hi[a], move[a] + h, 1e-5) << path << " axis " << a;
    }
    EXPECT_TRUE(read.warnings.empty()) << path << ": " << (read.warnings.empty() ? "" : read.warnings[0]);
}

// ---- formats read through Assimp ----

TEST(MeshImport, OffCubeWithQuadsIsTriangulated) {
    TempDir dir;
    std::string off = "OFF\n8 6 0\n";
    const Mesh cube = cubeMesh(1.0f);
    for (const auto& v : cube.vertices) off += std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
    off += "4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n";  // cubeMesh's quads
    const std::string path = writeFile(dir, "cube.off", off);
    expectCube(readMesh(path), 1.0f, glm::vec3(0), path);
    const std::string triangles = writeFile(dir, "CUBE.OFF", test::toOff(cubeMesh(0.5f)));
    expectCube(readMesh(triangles), 0.5f, glm::vec3(0), triangles);
}

TEST(MeshImport, GltfWithEmbeddedBufferComesOutInWorldSpace) {
    TempDir dir;
    const glm::vec3 move(1, 2, -3);
    const std::string path = writeFile(dir, "cube.gltf", test::toGltf(cubeMesh(0.5f), move));
    expectCube(readMesh(path), 0.5f, move, path);
}

TEST(MeshImport, GltfWithExternalBinBufferIsReadFromBesideIt) {
    TempDir dir;
    const Mesh cube = cubeMesh(2.0f);
    writeFile(dir, "cube.bin", test::gltfBuffer(cube));
    const std::string path = writeFile(dir, "cube.gltf", test::toGltf(cube, glm::vec3(0, 5, 0), "cube.bin"));
    expectCube(readMesh(path), 2.0f, glm::vec3(0, 5, 0), path);
}

TEST(MeshImport, GlbFromOurOwnWriterReadsBack) {
    TempDir dir;
    const std::string path = dir.file("cube.glb");
    writeGlb(cubeMesh(0.75f), path);
    expectCube(readMesh(path), 0.75f, glm::vec3(0), path);
    EXPECT_EQ(loadMeshShape(path).triangles.size(), 12u) << "the grammar's `mesh` reads it too";
}

TEST(MeshImport, ColladaCubeWithNodeTranslation) {
    TempDir dir;
    const glm::vec3 move(-1, 0.5f, 4);
    const std::string path = writeFile(dir, "cube.dae", test::toDae(cubeMesh(1.0f), move));
    expectCube(readMesh(path), 1.0f, move, path);
}

TEST(MeshImport, ThreeMfCube) {
    TempDir dir;
    const std::string path = writeFile(dir, "cube.3mf", test::to3mf(cubeMesh(1.5f)));
    expectCube(readMesh(path), 1.5f, glm::vec3(0), path);
}

TEST(MeshImport, SceneOfSeveralMeshesIsMergedIntoOne) {
    TempDir dir;
    // Two glTF nodes share the mesh: two cubes, 24 triangles.
    std::string gltf = test::toGltf(cubeMesh(0.5f), glm::vec3(0));
    const std::string one = "\"nodes\":[{\"mesh\":0,\"translation\":[0,0,0]}]";
    ASSERT_NE(gltf.find(one), std::string::npos);
    gltf.replace(gltf.find(one), one.size(),
                 "\"nodes\":[{\"mesh\":0,\"translation\":[0,0,0]},{\"mesh\":0,\"translation\":[3,0,0]}]");
    gltf.replace(gltf.find("\"nodes\":[0]"), 11, "\"nodes\":[0,1]");
    const std::string path = writeFile(dir, "two.gltf", gltf);
    const Mesh m = readMesh(path);
    EXPECT_EQ(m.triangles.size(), 24u);
    EXPECT_NEAR(test::signedVolume(m), 2.0, 1e-5);
    EXPECT_NEAR(test::bounds(m).hi.x, 3.5f, 1e-6);
}

TEST(MeshImport, KnownExtensionsIncludeTheCommonFormatsButNotOurOwn) {
    const std::vector<std::string> exts = assimpMeshExtensions();
    for (const char* e : {".off", ".gltf", ".glb", ".fbx", ".3mf", ".dae", ".3ds"})
        EXPECT_NE(std::find(exts.begin(), exts.end(), e), exts.end()) << e;
    for (const char* e : {".obj", ".ply", ".stl"}) EXPECT_EQ(std::find(exts.begin(), exts.end(), e), exts.end()) << e;
    EXPECT_TRUE(std::is_sorted(exts.begin(), exts.end()));
}

// ---- bad and hostile files: one InputError naming the file ----

TEST(MeshImportErrors, UnknownExtensionListsTheFormats) {
    TempDir dir;
    const std::string path = writeFile(dir, "cube.xyz", "0 0 0\n");
    expectInputError([&] { readMesh(path); }, {path, "unknown mesh extension '.xyz'", ".obj", ".glb", ".off", ".fbx"});
    const std::string none = writeFile(dir, "cube", "0 0 0\n");
    expectInputError([&] { readMesh(none); }, {none, "unknown mesh extension ''"});
}

TEST(MeshImportErrors, MissingFileDirectoryFifoAndEmptyFile) {
    TempDir dir;
    expectInputError([&] { readMesh(dir.file("absent.glb")); }, {dir.file("absent.glb"), "no such file"});
    std::filesystem::create_directory(dir.file("folder.fbx"));
    expectInputError([&] { readMesh(dir.file("folder.fbx")); }, {dir.file("folder.fbx"), "is a directory"});
    ASSERT_EQ(::mkfifo(dir.file("pipe.obj").c_str(), 0600), 0);  // reading it would block forever
    expectInputError([&] { readMesh(dir.file("pipe.obj")); }, {dir.file("pipe.obj"), "not a regular file"});
    for (const char* name : {"empty.glb", "empty.off", "empty.obj"}) {
        const std::string path = writeFile(dir, name, "");
        expectInputError([&] { readMesh(path); }, {path, "empty"});
    }
}

TEST(MeshImportErrors, FileOverTheSizeLimitIsRefusedBeforeReading) {
    TempDir dir;
    const std::string path = writeFile(dir, "cube.off", test::toOff(cubeMesh(1.0f)));
    MeshReadLimits limits;
    limits.maxFileBytes = 100;
    expectInputError([&] { readMesh(path, limits); }, {path, "over shapevo's limit of 100 bytes"});
    const std::string obj = writeFile(dir, "big.obj", std::string(200, '#'));
    expectInputError([&] { readMesh(obj, limits); }, {obj, "limit"});
}

TEST(MeshImportErrors, TruncatedOffAndGlbNameTheFile) {
    TempDir dir;
    const std::string off = writeFile(dir, "short.off", "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1");
    expectInputError([&] { readMesh(off); }, {off + ": ", "cannot read OFF mesh"});
    const std::string whole = dir.file("whole.glb");
    writeGlb(cubeMesh(1.0f), whole);
    const std::string bytes = test::readFile(whole);
    for (std::size_t keep : {bytes.size() / 2, std::size_t(30), std::size_t(12), bytes.size() - 4}) {
        const std::string path = writeFile(dir, "short" + std::to_string(keep) + ".glb", bytes.substr(0, keep));
        expectInputError([&] { readMesh(path); }, {path + ": ", "cannot read GLB mesh"});
    }
}

TEST(MeshImportErrors, OffAnnouncingABillionVerticesStaysInsideTheMemoryLimit) {
    TempDir dir;  // Assimp reserves for the counts it is told: 12 GB here, refused by the child's limit
    const std::string path = writeFile(dir, "huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n");
    expectInputError([&] { readMesh(path); }, {path + ": cannot read OFF mesh"});
}

// Inputs on which Assimp 5.2.5 itself crashes or hangs (found by fuzzing; the same bytes are in
// tests/fuzz/regressions/fuzz_mesh_import/): the sandbox turns each into one InputError.

TEST(MeshImportErrors, DirectXFaceIndexOutOfRangeCrashesAssimpNotShapevo) {
    TempDir dir;  // Assimp's X importer dies of SIGBUS on the index 44 of an 8-vertex mesh
    const std::string path = writeFile(dir, "cube.x",
                                       "xof 0302txt 0064\nMesh cube {\n 8;\n -1;-1;-1;,\n 1;-1;-1;,\n -1;1;-1;,\n"
                                       " 1;1;-1;,\n -1;-1;1;,\n 1;-1;1;,\n -1;1;1;,\n 1;1;1;;\n 6;\n 4;0,4,6,2;,\n"
                                       " 4;1,3,7,5;,\n 4;0,1,5,44;0,2,3,1;,\n 4;4,5,7,6;;\n}\n");
    expectInputError([&] { readMesh(path); }, {path + ": cannot read X mesh: Assimp could not import it: it crashed"});
}

TEST(MeshImportErrors, ThreeMfWithABadZipChecksumAbortsAssimpNotShapevo) {
    TempDir dir;  // an ai_assert in Assimp's zip reader calls abort() on a CRC mismatch
    std::string bytes = test::to3mf(cubeMesh(1.0f));
    const std::size_t at = bytes.find("<vertex x=\"-1\"");
    ASSERT_NE(at, std::string::npos);
    bytes[at + 12] = '2';  // the stored CRC no longer matches the data
    const std::string path = writeFile(dir, "bad-crc.3mf", bytes);
    expectInputError([&] { readMesh(path); }, {path + ": cannot read 3MF mesh: Assimp could not import it: it crashed"});
}

TEST(MeshImportErrors, SmdWithUnterminatedNodesHangsAssimpUntilTheTimeLimit) {
    TempDir dir;  // Assimp's SMD importer loops for ever on this 47-byte file (no newline at its end)
    const std::string path = writeFile(dir, "hang.smd", "vMrsion 1\nnodes\n0 \"root\" d1\nen\x02\nskele\xc4on\ntime 0");
    MeshReadLimits limits;
    limits.seconds = 0.5;
    limits.secondsPerMiB = 0;
    expectInputError([&] { readMesh(path, limits); }, {path + ": cannot read SMD mesh", "still running after 0.5 s"});
}

TEST(MeshImportErrors, RandomBytesGiveOneMessageForEveryFormat) {
    TempDir dir;
    std::mt19937 random(14);
    for (const char* ext : {".fbx", ".3mf", ".dae", ".glb", ".gltf", ".off", ".3ds", ".blend", ".x"}) {
        std::string bytes(3000, '\0');
        for (char& c : bytes) c = char(random());
        const std::string path = writeFile(dir, std::string("noise") + ext, bytes);
        const std::string message = expectInputError([&] { readMesh(path); }, {path + ": "});
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_LT(message.size(), 700u) << message;
    }
}

TEST(MeshImportErrors, NonFiniteCoordinateIsLocatedAndABadIndexNeverGetsThrough) {
    TempDir dir;
    const Mesh cube = cubeMesh(1.0f);
    std::string buffer = test::gltfBuffer(cube);
    const float inf = std::numeric_limits<float>::infinity();
    std::memcpy(buffer.data() + 12 * 5 + 4, &inf, 4);  // vertex 5's y
    writeFile(dir, "inf.bin", buffer);
    const std::string inf_ = writeFile(dir, "inf.gltf", test::toGltf(cube, glm::vec3(0), "inf.bin"));
    expectInputError([&] { readMesh(inf_); }, {inf_ + ":mesh 0 vertex 5: non-finite vertex coordinate"});
    buffer = test::gltfBuffer(cube);
    const std::uint32_t far = 99;
    std::memcpy(buffer.data() + 8 * 12 + 4 * 7, &far, 4);  // triangle 2's second corner
    writeFile(dir, "index.bin", buffer);
    const std::string index = writeFile(dir, "index.gltf", test::toGltf(cube, glm::vec3(0), "index.bin"));
    try {  // Assimp drops the triangle (then the cube is open) or refuses the file
        const Mesh m = readMesh(index);
        for (const auto& t : m.triangles)
            for (std::uint32_t i : t) EXPECT_LT(i, m.vertices.size());
        EXPECT_THROW(requireClosed(m, index), InputError);
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(index, 0), 0u) << e.what();
    }
}

TEST(MeshImportErrors, SceneWithoutTrianglesIsRejected) {
    TempDir dir;
    const std::string path = writeFile(dir, "lines.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n2 1 2\n");
    expectInputError([&] { readMesh(path); }, {path});
}

// ---- the PLY reader's warnings ----

TEST(MeshReader, PlyStrayHeaderLinesAreSkippedWithAWarning) {
    TempDir dir;
    const std::string blender = "Created by Blender 2.49 - www.blender.org, source file: 'cube.blend'";
    const std::string path = writeFile(dir, "blender.ply",
                                       "ply\nformat ascii 1.0\n" + blender +
                                           "\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                           "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                                           "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    const Mesh m = readMesh(path);
    EXPECT_EQ(m.triangles.size(), 4u);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], path + ": line 3: skipped the header line '" + blender +
                                 "' (not a PLY keyword; a comment needs 'comment' before it)");
}

TEST(MeshReader, ManyStrayPlyHeaderLinesGiveFiveWarningsAndACount) {
    TempDir dir;
    std::string header = "ply\nformat ascii 1.0\n";
    for (int i = 0; i < 8; ++i) header += "junk line " + std::to_string(i) + "\n";
    const std::string path = writeFile(dir, "junk.ply", header + "element vertex 3\nproperty float x\nproperty float y\n"
                                                                 "property float z\nelement face 1\nproperty list uchar int "
                                                                 "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const Mesh m = readMesh(path);
    ASSERT_EQ(m.warnings.size(), 6u);
    EXPECT_NE(m.warnings[0].find(path + ": line 3: skipped the header line 'junk line 0'"), std::string::npos);
    EXPECT_EQ(m.warnings[5], path + ": skipped 3 more header lines that start with no PLY keyword");
}

// ---- the sandbox ----

meshio::SandboxLimits quickLimits() {
    meshio::SandboxLimits l;
    l.seconds = 5;
    l.memoryBytes = 256ull << 20;
    l.maxOutputBytes = 1 << 20;
    return l;
}

TEST(SandboxedCall, ReturnsWhatTheChildProduced) {
    const auto r = meshio::sandboxedCall([] { return std::string("hello\0world", 11); }, quickLimits());
    EXPECT_EQ(r.outcome, meshio::SandboxResult::Outcome::Finished);
    EXPECT_EQ(r.output, std::string("hello\0world", 11));
}

TEST(SandboxedCall, ACrashInTheChildIsReportedNotSuffered) {
    const auto r = meshio::sandboxedCall([]() -> std::string { std::raise(SIGSEGV); return "survived"; }, quickLimits());
    EXPECT_EQ(r.outcome, meshio::SandboxResult::Outcome::Crashed);
    EXPECT_EQ(r.signal, SIGSEGV);
    EXPECT_NE(meshio::describeFailure(r, quickLimits()).find("crashed (signal 11"), std::string::npos);
    const auto thrown = meshio::sandboxedCall([]() -> std::string { throw 7; }, quickLimits());
    EXPECT_EQ(thrown.outcome, meshio::SandboxResult::Outcome::Failed);
}

TEST(SandboxedCall, AHangIsStoppedAtTheTimeLimit) {
    meshio::SandboxLimits l = quickLimits();
    l.seconds = 0.3;
    const auto r = meshio::sandboxedCall([]() -> std::string { for (;;) std::this_thread::sleep_for(std::chrono::seconds(1)); }, l);
    EXPECT_EQ(r.outcome, meshio::SandboxResult::Outcome::TimedOut);
    EXPECT_NE(meshio::describeFailure(r, l).find("0.3 s"), std::string::npos);
}

TEST(SandboxedCall, AHugeAllocationFailsInsideTheMemoryLimit) {
    const auto r = meshio::sandboxedCall(
        [] {
            std::string big(std::size_t(2) << 30, 'x');  // 2 GiB, over the child's 256 MiB
            return big.substr(0, 1);
        },
        quickLimits());
    // std::bad_alloc ends the child (Failed); under AddressSanitizer its out-of-memory report aborts it.
    EXPECT_TRUE(r.outcome == meshio::SandboxResult::Outcome::Failed || r.outcome == meshio::SandboxResult::Outcome::Crashed)
        << meshio::describeFailure(r, quickLimits());
}

TEST(SandboxedCall, TooMuchOutputIsCutOff) {
    meshio::SandboxLimits l = quickLimits();
    l.maxOutputBytes = 1000;
    const auto r = meshio::sandboxedCall([] { return std::string(100000, 'x'); }, l);
    EXPECT_EQ(r.outcome, meshio::SandboxResult::Outcome::OutputTooLarge);
    EXPECT_TRUE(r.output.empty());
}

TEST(SandboxedCall, LeavesNoChildBehind) {
    const test::ChildProcessWatch watch;  // children from before (other tests') do not count
    meshio::sandboxedCall([] { return std::string("x"); }, quickLimits());
    meshio::sandboxedCall([]() -> std::string { std::abort(); }, quickLimits());
    EXPECT_TRUE(watch.newChildren().empty()) << "every child is reaped";
}

}  // namespace
}  // namespace shapevo
