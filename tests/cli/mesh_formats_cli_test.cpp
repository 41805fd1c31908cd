// `shapevo target` with the mesh formats read through Assimp: an OFF cube makes a target, a PLY
// with a stray header line makes one with a warning, and a hostile GLB exits 2 with one message
// naming the file (and writes nothing).
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::runShapevo;
using test::TempDir;
using test::writeFile;

const char* kOffCube = "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
                       "4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n";

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(MeshFormatsCli, TargetFromAnOffCube) {
    TempDir dir;
    writeFile(dir.file("cube.off"), kOffCube);
    const auto r = runShapevo("target " + dir.file("cube.off") + " -o " + dir.file("t.vdb") + " --voxel-size 0.25");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("12 triangles"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("t.vdb")));
}

TEST(MeshFormatsCli, PlyStrayHeaderLineIsAWarningNotAnError) {
    TempDir dir;
    writeFile(dir.file("blender.ply"),
              "ply\nformat ascii 1.0\nCreated by Blender 2.49 - www.blender.org\nelement vertex 4\nproperty float x\n"
              "property float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    const auto r = runShapevo("target " + dir.file("blender.ply") + " -o " + dir.file("t.vdb") + " --voxel-size 0.1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("shapevo: warning: " + dir.file("blender.ply") + ": line 3: skipped the header line"),
              std::string::npos)
        << r.output;
}

TEST(MeshFormatsCli, HostileGlbExitsTwoWithOneMessage) {
    TempDir dir;
    // A GLB header that announces a 4 GiB file and a JSON chunk of 2 GiB.
    static const char bytes[] = "glTF\x02\x00\x00\x00\xff\xff\xff\xff\x00\x00\x00\x80JSON{\"asset\":";
    const std::string glb(bytes, sizeof bytes - 1);
    writeFile(dir.file("hostile.glb"), glb);
    const auto r = runShapevo("target " + dir.file("hostile.glb") + " -o " + dir.file("t.vdb"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(count(r.output, "shapevo: error: "), 1u) << r.output;
    EXPECT_NE(r.output.find(dir.file("hostile.glb") + ": cannot read GLB mesh"), std::string::npos) << r.output;
    EXPECT_EQ(count(r.output, "\n"), 1u) << "one line, no Assimp noise: " << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("t.vdb")));
}

TEST(MeshFormatsCli, TargetHelpNamesTheFormats) {
    const auto r = runShapevo("target --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* f : {"OFF", "glTF", "FBX", "3MF", ".glb", ".dae"}) EXPECT_NE(r.output.find(f), std::string::npos) << f;
}

}  // namespace
}  // namespace shapevo
