// `shapevo target` without --voxel-size (issue 40, item 2): the size is chosen to fit the mesh and
// said on the output, so a mesh modelled in centimetres needs no flag; with --voxel-size the size
// is used as given, nothing is announced, and a size that is far too small is still refused with
// "would be N voxels across (limit 20000)".
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::runShapevo;
using test::TempDir;
using test::writeFile;

/// A closed box from `lo` to `hi` as OBJ text (outward quads).
std::string boxObj(const double lo[3], const double hi[3]) {
    std::ostringstream s;
    for (int i = 0; i < 8; ++i) s << "v " << ((i & 1) ? hi[0] : lo[0]) << " " << ((i & 2) ? hi[1] : lo[1]) << " " << ((i & 4) ? hi[2] : lo[2]) << "\n";
    s << "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
    return s.str();
}

TEST(TargetVoxelSizeCli, AMeshInCentimetresNeedsNoFlagAndTheChosenSizeIsSaid) {
    TempDir dir;
    const double lo[3] = {0, 0, 0}, hi[3] = {250, 180, 60};  // a crate, in centimetres
    writeFile(dir.file("crate.obj"), boxObj(lo, hi));
    const auto r = runShapevo("target " + dir.file("crate.obj") + " -o " + dir.file("crate.vdb"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("voxel size: 1.95 (chosen: the longest side, 250 model units, in about 128 voxels; "
                            "--voxel-size sets another)\n"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" voxels of 1.95\nwrote " + dir.file("crate.vdb")), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("crate.vdb")));
}

TEST(TargetVoxelSizeCli, AGivenSizeIsUsedAsGivenAndTheLimitStays) {
    TempDir dir;
    const double lo[3] = {0, 0, 0}, hi[3] = {250, 180, 60};
    writeFile(dir.file("crate.obj"), boxObj(lo, hi));
    const auto tooSmall = runShapevo("target " + dir.file("crate.obj") + " -o " + dir.file("a.vdb") + " --voxel-size 0.01");
    EXPECT_EQ(tooSmall.exitCode, 2) << tooSmall.output;
    EXPECT_NE(tooSmall.output.find(dir.file("crate.obj") + ": voxel size 0.01 is too small: the mesh would be 31385 voxels "
                                                          "across (limit 20000)"),
              std::string::npos)
        << tooSmall.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.vdb")));
    const auto given = runShapevo("target " + dir.file("crate.obj") + " -o " + dir.file("b.vdb") + " --voxel-size 10");
    EXPECT_EQ(given.exitCode, 0) << given.output;
    EXPECT_EQ(given.output.find("voxel size:"), std::string::npos) << given.output;
    EXPECT_NE(given.output.find(" voxels of 10\nwrote "), std::string::npos) << given.output;
}

TEST(TargetVoxelSizeCli, HelpSaysHowTheSizeIsChosen) {
    const auto r = runShapevo("target --help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.output.find("chosen to fit the mesh"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/ 128"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace shapevo
