// A run folder nothing can hang, hijack or silently lose (issue 11), end to end with the binary:
// damage on one rank of two never hangs a resume, another run's checkpoint is refused and kept,
// a second writer is refused naming the holder, a checkpoint that cannot be written stops the
// run with exit 1, the seed survives a resume, a changed mesh is refused unless allowed, and
// SIGINT / SIGHUP checkpoint like SIGTERM. Commands run under `timeout`, so a hang fails.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "../test_support.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "run/run_folder_lock.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::runCommand;
using test::sourcePath;
using test::spaceshipConfig;
using test::TempDir;
using test::writeFile;

const std::string kSmallRunFolder = " --set ga.population=30 --set ga.elitism=4 --set ga.tournament=5 --set migration.interval=3"
                           " --set migration.count=3 --set checkpoint.interval=10 --set checkpoint.keep=10 -q";


/// shapevo under `timeout 120` (exit 124 if it hangs), on `ranks` MPI ranks (0: no mpirun).
test::CommandResult shapevo(int ranks, const std::string& args) {
    const std::string bin = std::string(SHAPEVO_BIN) + " " + args;
    if (ranks == 0) return runCommand("timeout 120 " + bin);
    return runCommand("timeout 120 " + test::mpirunWords(ranks) + " " + bin);
}

/// MANIFEST without the line of `name` (the file stays in the folder).
void dropFromManifest(const std::string& checkpoint, const std::string& name) {
    std::ifstream in(checkpoint + "/MANIFEST");
    std::string kept, line;
    while (std::getline(in, line))
        if (line.rfind(name + " ", 0) != 0) kept += line + "\n";
    writeFile(checkpoint + "/MANIFEST", kept);
}

void xorBytes(const std::string& path, std::size_t from, std::size_t to, char mask) {
    std::string bytes = readFile(path);
    ASSERT_GT(bytes.size(), to);
    for (std::size_t i = from; i <= to; ++i) bytes[i] ^= mask;
    writeFile(path, bytes);
}

TEST(RunFolder, ForgedIslandOnOneRankNeverHangsAndEveryRankFallsBack) {
    test::LeakCheckedRanks leaks;  // this MPI path runs under LeakSanitizer too
    for (bool rebuildManifest : {false, true}) {
        TempDir dir;
        const std::string run = dir.file("run");
        ASSERT_EQ(shapevo(2, "run " + spaceshipConfig() + " --seed 3 --set ga.generations=20 --out " + run + kSmallRunFolder).exitCode, 0);
        const std::string k = run + "/checkpoint-000020";
        dropFromManifest(k, "island-0001.h5");
        xorBytes(k + "/island-0001.h5", 1000, 1007, 0x5a);
        if (rebuildManifest) writeManifest(k, {"run.h5", "island-0000.h5", "island-0001.h5"});
        const auto r = shapevo(2, "resume " + run + " --generations 25 -q");
        EXPECT_EQ(r.exitCode, 0) << "rebuilt MANIFEST: " << rebuildManifest << "\n" << r.output;
        EXPECT_NE(r.output.find("checkpoint " + k), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("trying the one before it"), std::string::npos) << r.output;
        EXPECT_NE(readFile(run + "/summary.json").find("\"generations\": 25"), std::string::npos);
    }
}

TEST(RunFolder, AnotherRunsCheckpointIsRefusedByNameAndNeverPrunedOrAdopted) {
    TempDir dir;
    const std::string a = dir.file("a"), b = dir.file("b");
    ASSERT_EQ(shapevo(0, "run " + spaceshipConfig() + " --seed 1 --set ga.generations=10 --out " + a + kSmallRunFolder +
                             " --set checkpoint.keep=1").exitCode, 0);
    ASSERT_EQ(shapevo(0, "run " + spaceshipConfig() + " --seed 2 --set ga.generations=70 --out " + b + kSmallRunFolder).exitCode, 0);
    fs::copy(b + "/checkpoint-000070", a + "/checkpoint-000070", fs::copy_options::recursive);
    const std::string foreign = readFile(a + "/checkpoint-000070/run.h5");
    const auto plain = shapevo(0, "resume " + a + " --generations 20 -q");
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_NE(plain.output.find(a + "/checkpoint-000070 belongs to another run"), std::string::npos) << plain.output;
    EXPECT_EQ(readFile(a + "/checkpoint-000070/run.h5"), foreign) << "the other run's checkpoint is untouched";
    EXPECT_NE(readFile(a + "/summary.json").find("\"seed\": 1"), std::string::npos);
    EXPECT_TRUE(fs::exists(a + "/checkpoint-000020"));
}

TEST(RunFolder, ASecondWriterIsRefusedNamingTheHolder) {
    TempDir dir;
    const std::string run = dir.file("run");
    ASSERT_EQ(shapevo(0, "run " + spaceshipConfig() + " --set ga.generations=10 --out " + run + kSmallRunFolder).exitCode, 0);
    {
        const RunFolderLock held(run);  // this test process is "the other shapevo"
        const auto r = shapevo(0, "resume " + run + " --generations 20 -q");
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("is in use by another shapevo"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("pid " + std::to_string(::getpid())), std::string::npos) << r.output;
    }
    EXPECT_EQ(shapevo(0, "resume " + run + " --generations 20 -q").exitCode, 0) << "released with its holder";
}

TEST(RunFolder, ACheckpointThatCannotBeWrittenStopsTheRunWithExitOne) {
    TempDir dir;
    const std::string run = dir.file("run");
    // Files may grow to 16 KiB: the run folder's small files fit, an island file does not
    // (write() fails with EFBIG; SIGXFSZ is ignored as the shell's trap sets it).
    const auto r = runCommand("sh -c 'trap \"\" XFSZ; ulimit -f 16; exec timeout 120 " + std::string(SHAPEVO_BIN) + " run " +
                              spaceshipConfig() + " --set ga.generations=30 --out " + run + kSmallRunFolder + " --set checkpoint.interval=5'");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("checkpoint at generation 5 could not be written"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("there is no complete checkpoint of this run yet"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(run + "/summary.json")) << "no summary claims a finished run";
}

TEST(RunFolder, TheSeedGivenOnTheCommandLineSurvivesAResume) {
    TempDir dir;
    const std::string run = dir.file("run");
    ASSERT_EQ(shapevo(0, "run " + spaceshipConfig() + " --seed 99 --set ga.generations=10 --out " + run + kSmallRunFolder).exitCode, 0);
    ASSERT_EQ(shapevo(0, "resume " + run + " --generations 20 -q").exitCode, 0);
    EXPECT_NE(readFile(run + "/summary.json").find("\"seed\": 99"), std::string::npos) << readFile(run + "/summary.json");
}

/// A copy of the spaceship grammar whose bodies are `mesh "part.obj"`, and a config using it.
std::string meshRun(const TempDir& dir) {
    std::string grammar = readFile(sourcePath("grammars/spaceship.grammar"));
    const auto body = grammar.find("  box\n");
    grammar.replace(body, 6, "  mesh \"part.obj\"\n");
    writeFile(dir.file("part.obj"), "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n");
    return test::configWithGrammar(dir, grammar, "ship");
}

TEST(RunFolder, AChangedMeshIsRefusedByNameUnlessAllowedAndThenRecorded) {
    TempDir dir;
    const std::string cfg = meshRun(dir), run = dir.file("run");
    ASSERT_EQ(shapevo(0, "run " + cfg + " --set ga.generations=10 --out " + run + kSmallRunFolder).exitCode, 0);
    writeFile(dir.file("part.obj"), readFile(dir.file("part.obj")) + "# changed\n");
    const auto refused = shapevo(0, "resume " + run + " --generations 20 -q");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("part.obj changed"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("--allow-changed-inputs"), std::string::npos) << refused.output;
    const auto allowed = shapevo(0, "resume " + run + " --generations 20 -q --allow-changed-inputs");
    ASSERT_EQ(allowed.exitCode, 0) << allowed.output;
    EXPECT_NE(readFile(run + "/summary.json").find("\"changed_inputs\": [\"mesh "), std::string::npos)
        << readFile(run + "/summary.json");
}

TEST(RunFolder, SigintAndSighupCheckpointAndExitZero) {
    for (int signal : {SIGINT, SIGHUP}) {
        TempDir dir;
        const std::string run = dir.file("run");
        test::CommandResult r;
        std::thread runner([&] {
            r = runCommand(std::string(SHAPEVO_BIN) + " run " + spaceshipConfig() + " --set ga.generations=100000 --out " + run + kSmallRunFolder);
        });
        // wait until the run is under way (its first checkpoint), then signal the shapevo process only
        for (int i = 0; i < 1200 && !fs::exists(run + "/checkpoint-000010"); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        runCommand("pkill -" + std::to_string(signal) + " -f '^" + std::string(SHAPEVO_BIN) + " run .*" + run + "'");
        runner.join();
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(signal == SIGINT ? "stopped on SIGINT" : "stopped on SIGHUP"), std::string::npos) << r.output;
        EXPECT_TRUE(fs::exists(run + "/summary.json"));
        EXPECT_FALSE(listCheckpoints(run).empty());
    }
}

}  // namespace
}  // namespace shapevo
