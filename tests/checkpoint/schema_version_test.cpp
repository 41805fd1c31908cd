// A checkpoint of another schema (1: FNV-like checksums, before XXH3-64) is refused with a message
// naming both versions, for run.h5 and for island files alike.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <functional>
#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint_test_util.hpp"

namespace shapevo {
namespace {

/// Rewrites the root attribute schema_version of an HDF5 file in place.
void setSchemaVersion(const std::string& path, std::uint32_t version) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t a = H5Aopen(f, "schema_version", H5P_DEFAULT);
    ASSERT_GE(a, 0);
    ASSERT_GE(H5Awrite(a, H5T_NATIVE_UINT32, &version), 0);
    H5Aclose(a);
    H5Fclose(f);
}

void expectRefusedNamingBothVersions(const std::function<void()>& read) {
    try {
        read();
        FAIL() << "a schema 1 file was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("schema 1"), std::string::npos) << what;
        EXPECT_NE(what.find("reads " + std::to_string(kCheckpointSchemaVersion)), std::string::npos) << what;
    }
}

TEST(CheckpointSchema, ARunFileOfSchemaOneIsRefusedNamingBothVersions) {
    test::TempDir dir;
    writeRunMetadata(dir.file("run.h5"), test::makeRun(2));
    setSchemaVersion(dir.file("run.h5"), 1);
    expectRefusedNamingBothVersions([&] { readRunMetadata(dir.file("run.h5")); });
}

TEST(CheckpointSchema, AnIslandFileOfSchemaOneIsRefusedNamingBothVersions) {
    test::TempDir dir;
    writeIslandFile(dir.file("island-0000.h5"), test::makeIsland(0));
    setSchemaVersion(dir.file("island-0000.h5"), 1);
    expectRefusedNamingBothVersions([&] { readIslandFile(dir.file("island-0000.h5"), test::spaceship(), test::kLimits); });
}

}  // namespace
}  // namespace shapevo
