// `shapevo target` on imperfect meshes (issue 14, line 2), through the real binary: a mesh with
// holes is filled and reported ("N open edges in M holes: filled", the inside volume and voxel
// count, "wrote"); a closed mesh is reported closed; an open sheet is refused with exit code 2,
// a message naming the file, and no .vdb.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../mesh/cube_mesh.hpp"
#include "../mesh/imperfect_meshes.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using namespace test;

std::string objText(const Mesh& m) {
    std::ostringstream s;
    s.precision(9);
    for (const glm::vec3& v : m.vertices) s << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& t : m.triangles) s << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    return s.str();
}

TEST(TargetRepairCli, HolesAreFilledAndTheReportSaysWhatWasFoundAndDone) {
    TempDir dir;
    // Two single-triangle holes (3 open edges each) and one quad (4).
    const std::string mesh = writeFile(dir, "holed.obj", objText(withoutTriangles(gridCube(0.95f, 4), {0, 1, 40, 100})));
    const CommandResult r = runShapevo("target " + mesh + " -o " + dir.file("holed.vdb") + " --voxel-size 0.25");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("mesh: 188 triangles, 10 open edges in 3 holes: filled (4 triangles added)\n"), std::string::npos) << r.output;
    // The whole cube: 7^3 voxel centres (0, +-0.25, +-0.5, +-0.75) of 0.25^3 each.
    EXPECT_NE(r.output.find("inside: volume 5.35938 (model units^3), 343 voxels of 0.25"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("wrote " + dir.file("holed.vdb")), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("holed.vdb")));
}

TEST(TargetRepairCli, AClosedMeshIsReportedClosed) {
    TempDir dir;
    const std::string mesh = writeFile(dir, "cube.obj", objText(cubeMesh(0.95f)));
    const CommandResult r = runShapevo("target " + mesh + " -o " + dir.file("cube.vdb") + " --voxel-size 0.25");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("mesh: 12 triangles, closed\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("343 voxels of 0.25"), std::string::npos) << r.output;
}

TEST(TargetRepairCli, AnOpenSheetIsRefusedAndNoFileIsWritten) {
    TempDir dir;
    const std::string mesh = writeFile(dir, "sheet.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    const CommandResult r = runShapevo("target " + mesh + " -o " + dir.file("sheet.vdb"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + mesh + ": the inside of the mesh cannot be determined"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("sheet.vdb")));
}

}  // namespace
}  // namespace shapevo
