// `shapevo inspect` and `shapevo export` accept a run folder, a checkpoint folder or one of its
// files (island-NNNN.h5, run.h5), all meaning the same checkpoint; anything else is exit 2 with a
// message naming the path (checkpoint/checkpoint_path.hpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;

namespace fs = std::filesystem;

const std::string kSmallCheckpoint = " --set ga.population=20 --set ga.generations=4 --set ga.elitism=4 -q";

/// A finished spaceship run in `dir`/run; its end-of-run checkpoint is checkpoint-000004.
void runSmall(const TempDir& dir) {
    const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + dir.file("run") + kSmallCheckpoint);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(fs::exists(dir.file("run/checkpoint-000004/island-0000.h5")));
}

/// Every way of naming the run's newest checkpoint.
std::vector<std::string> checkpointPaths(const TempDir& dir) {
    return {dir.file("run"), dir.file("run/"), dir.file("run/checkpoint-000004"), dir.file("run/checkpoint-000004/"),
            dir.file("run/checkpoint-000004/island-0000.h5"), dir.file("run/checkpoint-000004/run.h5")};
}

void expectRefused(const test::CommandResult& r, const std::string& path) {
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + path + ": "), std::string::npos) << "expected the path " << path << " in: " << r.output;
}

TEST(CheckpointPath, InspectAcceptsRunFolderCheckpointFolderAndIslandFile) {
    TempDir dir;
    runSmall(dir);
    for (const std::string& path : checkpointPaths(dir)) {
        const auto r = runShapevo("inspect " + path);
        ASSERT_EQ(r.exitCode, 0) << path << ": " << r.output;
        EXPECT_EQ(r.output.rfind("checkpoint-000004: complete", 0), 0u) << path << ": " << r.output;
        EXPECT_NE(r.output.find("generation   4\n"), std::string::npos) << path << ": " << r.output;
    }
}

TEST(CheckpointPath, ExportAcceptsRunFolderCheckpointFolderAndIslandFile) {
    TempDir dir;
    runSmall(dir);
    const std::string bestObj = readFile(dir.file("run/best.obj"));
    ASSERT_FALSE(bestObj.empty());
    const std::vector<std::string> paths = checkpointPaths(dir);
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const std::string& path = paths[i];
        std::string name = std::to_string(i);  // a new file each time: export never overwrites
        name += ".obj";
        const std::string out = dir.file(name);
        const auto r = runShapevo("export " + path + " --best -o " + out);
        ASSERT_EQ(r.exitCode, 0) << path << ": " << r.output;
        EXPECT_EQ(readFile(out), bestObj) << path << ": the newest checkpoint's best is the run's best";
    }
    const auto vdb = runShapevo("export " + dir.file("run/checkpoint-000004/island-0000.h5") + " --best -o " + dir.file("m.vdb"));
    EXPECT_EQ(vdb.exitCode, 0) << vdb.output;
    EXPECT_TRUE(fs::exists(dir.file("m.vdb")));
}

TEST(CheckpointPath, AnythingElseIsExitTwoNamingThePath) {
    TempDir dir;
    runSmall(dir);
    fs::create_directories(dir.file("empty"));
    fs::copy_file(dir.file("run/checkpoint-000004/island-0000.h5"), dir.file("island-0000.h5"));
    fs::copy_file(dir.file("run/checkpoint-000004/island-0000.h5"), dir.file("run/checkpoint-000004/island-0007.h5"));
    fs::create_directories(dir.file("damaged"));
    fs::copy(dir.file("run/checkpoint-000004"), dir.file("damaged/checkpoint-000004"));
    fs::resize_file(dir.file("damaged/checkpoint-000004/run.h5"), 10);
    const std::vector<std::string> wrong = {
        dir.file("missing"),                                // does not exist
        dir.file("run/summary.json"),                       // a file, not a checkpoint file
        dir.file("run/best.genome"),                        // another file
        dir.file("empty"),                                  // a folder without checkpoints
        dir.file("island-0000.h5"),                         // an island file outside a checkpoint
        dir.file("run/checkpoint-000004/island-0007.h5"),   // not listed in the MANIFEST
        dir.file("damaged"),                                // a run folder without a complete checkpoint
    };
    for (const std::string& path : wrong) {
        SCOPED_TRACE(path);
        expectRefused(runShapevo("inspect " + path), path);
        expectRefused(runShapevo("export " + path + " --best -o " + dir.file("out.obj")), path);
        EXPECT_FALSE(fs::exists(dir.file("out.obj")));
    }
}

TEST(CheckpointPath, HelpSaysWhichPathsAreAccepted) {
    for (const char* command : {"inspect", "export"}) {
        const auto r = runShapevo(std::string(command) + " --help");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        for (const char* kind : {"run folder", "checkpoint folder", "island-NNNN.h5", "run.h5"})
            EXPECT_NE(r.output.find(kind), std::string::npos) << command << " --help lacks '" << kind << "': " << r.output;
    }
}

}  // namespace
}  // namespace shapevo
