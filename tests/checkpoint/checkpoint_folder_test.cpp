// Checkpoint folders: names, newest-first listing that ignores everything else, pruning to the
// newest N plus removal of stale partial folders, publishing by rename, and the inspect summary.
#include <filesystem>

#include <gtest/gtest.h>

#include "checkpoint_test_util.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names(const std::vector<std::string>& paths) {
    std::vector<std::string> out;
    for (const std::string& p : paths) out.push_back(fs::path(p).filename().string());
    return out;
}

void makeFolders(const test::TempDir& dir, std::initializer_list<const char*> folders) {
    for (const char* f : folders) fs::create_directories(dir.path() / f);
}

TEST(CheckpointFolders, NamesArePaddedNumbers) {
    EXPECT_EQ(checkpointName(400), "checkpoint-000400");
    EXPECT_EQ(checkpointName(1234567), "checkpoint-1234567");
    EXPECT_EQ(islandFileName(3), "island-0003.h5");
    EXPECT_EQ(islandFileName(12345), "island-12345.h5");
}

TEST(CheckpointFolders, ListIsNewestFirstByNumberAndIgnoresOtherNames) {
    test::TempDir dir;
    makeFolders(dir, {"checkpoint-000010", "checkpoint-000200", "checkpoint-000030", "checkpoint-1000000",
                      ".checkpoint-000500.partial", "checkpoint-12", "checkpoint-00001x", "checkpoint-000050.old",
                      "best"});
    test::writeFile(dir.file("checkpoint-000400"), "a file, not a folder");
    EXPECT_EQ(names(listCheckpoints(dir.path().string())),
              (std::vector<std::string>{"checkpoint-1000000", "checkpoint-000200", "checkpoint-000030", "checkpoint-000010"}));
    EXPECT_EQ(listCheckpoints(dir.file("no-such-run")), std::vector<std::string>{});
}

TEST(CheckpointFolders, PruneKeepsNewestAndRemovesPartialFolders) {
    test::TempDir dir;
    for (std::uint32_t g : {10u, 20u, 30u, 40u}) test::writeCheckpoint(dir.path(), g);
    const std::string foreign = "ffeeddccbbaa99887766554433221100";
    test::writeCheckpoint(dir.path(), 25, 1, foreign);  // another run's: never pruned
    makeFolders(dir, {".checkpoint-000050.partial", ".checkpoint-000005.partial", ".checkpoint-000040.replaced",
                      "checkpoint-000050.old", "best", "checkpoint-000015"});
    test::writeFile(dir.file(".checkpoint-000050.partial/island-0000.h5"), "half written");
    pruneCheckpoints(dir.path().string(), 2, test::kRunId);
    EXPECT_EQ(names(listCheckpoints(dir.path().string())),
              (std::vector<std::string>{"checkpoint-000040", "checkpoint-000030", "checkpoint-000025", "checkpoint-000015"}))
        << "the other run's checkpoint and the unreadable (empty) one are not provably ours: kept";
    EXPECT_FALSE(fs::exists(dir.path() / ".checkpoint-000050.partial"));
    EXPECT_FALSE(fs::exists(dir.path() / ".checkpoint-000005.partial"));
    EXPECT_FALSE(fs::exists(dir.path() / ".checkpoint-000040.replaced"));
    EXPECT_TRUE(fs::exists(dir.path() / "checkpoint-000050.old"));  // not ours: untouched
    EXPECT_TRUE(fs::exists(dir.path() / "best"));
    pruneCheckpoints(dir.path().string(), 0, test::kRunId);  // never removes the newest
    EXPECT_EQ(names(listCheckpoints(dir.path().string())),
              (std::vector<std::string>{"checkpoint-000040", "checkpoint-000025", "checkpoint-000015"}));
}

TEST(CheckpointFolders, PublishRenamesThePartialFolder) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 7);
    EXPECT_TRUE(fs::exists(cp + "/MANIFEST"));
    EXPECT_FALSE(fs::exists(dir.path() / ".checkpoint-000007.partial"));
    EXPECT_EQ(verifyCheckpoint(cp), "");
}

TEST(CheckpointFolders, PublishReplacesADamagedFolderOfTheSameGeneration) {
    test::TempDir dir;
    test::writeCheckpoint(dir.path(), 10);
    const std::string damaged = test::writeCheckpoint(dir.path(), 20);
    fs::resize_file(damaged + "/island-0000.h5", 100);
    ASSERT_NE(verifyCheckpoint(damaged), "");
    // A resume went back to generation 10 and reached 20 again.
    const std::string again = test::writeCheckpoint(dir.path(), 20);
    EXPECT_EQ(again, damaged);
    EXPECT_EQ(verifyCheckpoint(again), "");
    EXPECT_EQ(names(listCheckpoints(dir.path().string())),
              (std::vector<std::string>{"checkpoint-000020", "checkpoint-000010"}));
    EXPECT_FALSE(fs::exists(dir.path() / ".checkpoint-000020.replaced"));
}

TEST(CheckpointFolders, NewestCompleteCheckpointIsFoundPastADamagedOne) {
    test::TempDir dir;
    test::writeCheckpoint(dir.path(), 10);
    const std::string newest = test::writeCheckpoint(dir.path(), 20);
    fs::resize_file(newest + "/run.h5", 100);
    std::string chosen;
    for (const std::string& cp : listCheckpoints(dir.path().string()))
        if (verifyCheckpoint(cp).empty()) {
            chosen = cp;
            break;
        }
    EXPECT_EQ(fs::path(chosen).filename(), "checkpoint-000010");
}

TEST(CheckpointInspect, DescribesRunAndEachIsland) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 2);
    const std::string text = describeCheckpoint(cp, false);
    const std::string schema = "schema       " + std::to_string(kCheckpointSchemaVersion);
    for (const std::string& expected : {std::string("checkpoint-000005: complete"), std::string("generation   5"),
                                        std::string("islands      2"), std::string("target hash  0123456789abcdef"),
                                        std::string("spaceship-test"), schema})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
    EXPECT_NE(text.find("seed         " + std::to_string(test::makeRun(2).seed)), std::string::npos) << text;
    EXPECT_NE(text.find("\n       1           24 "), std::string::npos) << text;  // island 1: 24 individuals
    EXPECT_EQ(text.find("[ga]"), std::string::npos);
    const std::string verbose = describeCheckpoint(cp, true);
    EXPECT_NE(verbose.find("population = 24"), std::string::npos) << verbose;
}

TEST(CheckpointInspect, IncompleteCheckpointIsAnInputErrorSayingWhy) {
    test::TempDir dir;
    const std::string cp = test::writeCheckpoint(dir.path(), 5, 2);
    fs::remove(cp + "/island-0001.h5");
    try {
        describeCheckpoint(cp, false);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("island-0001.h5: missing"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace shapevo
