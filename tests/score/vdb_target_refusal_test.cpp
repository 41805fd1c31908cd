// VDB targets refused with the right words (issue 11, rows 13 and 14): a truncated file says it
// is truncated or unreadable (not "holds no float grid"), with OpenVDB's message cut short; a
// float grid that is not a level set is refused naming the file and the grid.
#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "../mesh/cube_mesh.hpp"
#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "score/volume/vdb_target_file.hpp"

namespace shapevo {
namespace {

using test::TempDir;

std::string refusal(const std::string& path) {
    try {
        loadVolumeTarget({{path}});
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "accepted " << path;
    return "";
}

TEST(VdbTargetRefusal, ATruncatedFileSaysItIsTruncated) {
    TempDir dir;
    const std::string whole = dir.file("cube.vdb");
    writeTargetVdb(test::cubeMesh(1.0f), 0.1, "cube.obj", whole);
    const std::string bytes = test::readFile(whole);
    for (const std::size_t n : {std::size_t(0), std::size_t(8), std::size_t(10), std::size_t(100), std::size_t(300),
                                bytes.size() / 2, bytes.size() - 100}) {
        const std::string cut = dir.file("cut-" + std::to_string(n) + ".vdb");
        test::writeFile(cut, bytes.substr(0, n));
        const std::string what = refusal(cut);
        EXPECT_EQ(what.rfind(cut + ": ", 0), 0u) << what;
        EXPECT_NE(what.find("truncated or unreadable"), std::string::npos) << n << ": " << what;
        EXPECT_EQ(what.find("no float grid"), std::string::npos) << n << ": " << what;
        EXPECT_LT(what.size(), cut.size() + 250) << n << ": " << what;
    }
}

TEST(VdbTargetRefusal, AFloatGridThatIsNotALevelSetIsRefusedNamingFileAndGrid) {
    TempDir dir;
    const std::string levelSet = dir.file("cube.vdb");
    writeTargetVdb(test::cubeMesh(1.0f), 0.2, "cube.obj", levelSet);
    openvdb::io::File in(levelSet);
    in.open();
    const openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(in.getGrids()->front());
    in.close();
    for (const auto cls : {openvdb::GRID_UNKNOWN, openvdb::GRID_STAGGERED}) {
        const openvdb::FloatGrid::Ptr other = grid->deepCopy();
        other->setName("density");
        other->setGridClass(cls);
        const std::string path = dir.file("class-" + std::to_string(int(cls)) + ".vdb");
        openvdb::io::File(path).write({other});
        const std::string what = refusal(path);
        EXPECT_EQ(what.rfind(path + ": grid 'density' is not a level set", 0), 0u) << what;
    }
    // among several float grids the level set is the target
    const openvdb::FloatGrid::Ptr aux = grid->deepCopy();
    aux->setName("aux");
    aux->setGridClass(openvdb::GRID_UNKNOWN);
    const openvdb::FloatGrid::Ptr shape = grid->deepCopy();
    shape->setName("shape");
    const std::string both = dir.file("both.vdb");
    openvdb::io::File(both).write({aux, shape});
    EXPECT_EQ(loadVolumeTarget({{both}}).fillCount, loadVolumeTarget({{levelSet}}).fillCount);
}

}  // namespace
}  // namespace shapevo
