// A checkpoint of another schema (1: FNV-like checksums, before XXH3-64; 2: a curve without its iou
// column) is refused with a message naming both versions, for run.h5 and for island files alike.
#include <gtest/gtest.h>

#include <cmath>
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
        EXPECT_NE(what.find("reads " + std::to_string(kOldestReadableSchemaVersion) + " to " +
                            std::to_string(kCheckpointSchemaVersion)),
                  std::string::npos)
            << what;
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
    expectRefusedNamingBothVersions([&] { readIslandFile(dir.file("island-0000.h5"), test::spaceshipFamily(), test::kLimits); });
}

// A real schema 2 checkpoint (tests/data/schema2-checkpoint/README.md: written by the shapevo of
// before the curve's iou column) is still read: a run checkpointed then resumes. Its curve rows
// have no IoU (NaN), everything else is as written.
TEST(CheckpointSchema, ASchemaTwoCheckpointIsReadWithoutCurveIoU) {
    const std::string dir = test::sourcePath("tests/data/schema2-checkpoint/");
    const RunMetadata m = readRunMetadata(dir + "run.h5");
    EXPECT_EQ(m.schemaVersion, 2u);
    EXPECT_EQ(m.generation, 6u);
    ASSERT_EQ(m.curve.size(), 6u);
    for (std::size_t i = 0; i < m.curve.size(); ++i) {
        EXPECT_EQ(m.curve[i].generation, i + 1);
        EXPECT_TRUE(std::isnan(m.curve[i].iou));
        EXPECT_TRUE(std::isfinite(m.curve[i].best));
    }
    EXPECT_GE(m.curve.back().best, m.curve.front().best);
    const IslandState s = readIslandFile(dir + "island-0000.h5", test::spaceshipFamily(), GenomeLimits{100});
    EXPECT_EQ(s.runId, m.runId);
    EXPECT_EQ(s.population.size(), 20u);
    ASSERT_EQ(s.curve.size(), 6u);
    EXPECT_TRUE(std::isnan(s.curve.back().iou));
    EXPECT_EQ(s.curve.back().best, m.curve.back().best);
}

// A real schema 3 checkpoint (tests/data/schema3-checkpoint/README.md: rank 0 of a 2-rank sync
// run, before islands stored their migrants in flight) is still read: no migrants waiting.
TEST(CheckpointSchema, ASchemaThreeCheckpointIsReadWithNoMigrantsWaiting) {
    const std::string dir = test::sourcePath("tests/data/schema3-checkpoint/");
    const RunMetadata m = readRunMetadata(dir + "run.h5");
    EXPECT_EQ(m.schemaVersion, 3u);
    EXPECT_EQ(m.generation, 6u);
    EXPECT_EQ(m.ranks, 2);
    const IslandState s = readIslandFile(dir + "island-0000.h5", test::spaceshipFamily(), GenomeLimits{100});
    EXPECT_EQ(s.runId, m.runId);
    EXPECT_EQ(s.population.size(), 20u);
    EXPECT_EQ(s.arrivals.size(), 0u);
    ASSERT_EQ(s.curve.size(), 6u);
    EXPECT_FALSE(std::isnan(s.curve.back().iou));
}

// A schema 3 file whose schema_version was set to 2 (its attributes no longer match their
// checksum, and its curve has seven columns) is refused, naming the file.
TEST(CheckpointSchema, AFileWhoseSchemaWasChangedIsRefused) {
    test::TempDir dir;
    writeRunMetadata(dir.file("run.h5"), test::makeRun(2));
    test::setRootU32Attribute(dir.file("run.h5"), "schema_version", 2);
    try {
        readRunMetadata(dir.file("run.h5"));
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.file("run.h5"));
    }
}

}  // namespace
}  // namespace shapevo
