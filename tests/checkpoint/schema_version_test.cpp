// A checkpoint of another schema (1: FNV-like checksums, before XXH3-64; 2: a curve without its iou
// column) is refused with a message naming both versions, for run.h5 and for island files alike.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint_test_util.hpp"

namespace shapevo {
namespace {

void expectRefusedNamingBothVersions(const std::function<void()>& read, int old = 1) {
    try {
        read();
        FAIL() << "a schema " << old << " file was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("schema " + std::to_string(old)), std::string::npos) << what;
        EXPECT_NE(what.find("reads " + std::to_string(kCheckpointSchemaVersion)), std::string::npos) << what;
    }
}

TEST(CheckpointSchema, ARunFileOfSchemaOneIsRefusedNamingBothVersions) {
    test::TempDir dir;
    writeRunMetadata(dir.file("run.h5"), test::makeRun(2));
    test::setRootU32Attribute(dir.file("run.h5"), "schema_version", 1);
    expectRefusedNamingBothVersions([&] { readRunMetadata(dir.file("run.h5")); });
}

TEST(CheckpointSchema, AnIslandFileOfSchemaOneIsRefusedNamingBothVersions) {
    test::TempDir dir;
    writeIslandFile(dir.file("island-0000.h5"), test::makeIsland(0));
    test::setRootU32Attribute(dir.file("island-0000.h5"), "schema_version", 1);
    expectRefusedNamingBothVersions([&] { readIslandFile(dir.file("island-0000.h5"), test::spaceship(), test::kLimits); });
}

TEST(CheckpointSchema, ASchemaTwoCheckpointWithoutCurveIoUIsRefusedNamingBothVersions) {
    test::TempDir dir;
    writeRunMetadata(dir.file("run.h5"), test::makeRun(2));
    test::setRootU32Attribute(dir.file("run.h5"), "schema_version", 2);
    expectRefusedNamingBothVersions([&] { readRunMetadata(dir.file("run.h5")); }, 2);
    writeIslandFile(dir.file("island-0000.h5"), test::makeIsland(0));
    test::setRootU32Attribute(dir.file("island-0000.h5"), "schema_version", 2);
    expectRefusedNamingBothVersions([&] { readIslandFile(dir.file("island-0000.h5"), test::spaceship(), test::kLimits); }, 2);
}

}  // namespace
}  // namespace shapevo
