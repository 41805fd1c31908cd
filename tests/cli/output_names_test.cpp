// Names and paths of outputs (issue 11, rows 11 and 12): run.name is a plain folder name, so
// runs/<name> never leaves runs/; an output file needs an extension its command writes. Either
// mistake is exit 2 with a message saying what is accepted, and nothing is created.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::runCommand;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

std::size_t entries(const fs::path& folder) {
    return fs::exists(folder) ? std::size_t(std::distance(fs::directory_iterator(folder), {})) : 0;
}

TEST(OutputNames, RunNameMustBeAPlainName) {
    TempDir dir;
    fs::create_directories(dir.file("cwd"));
    for (const std::string name : {"../../evil", "", ".", "..", "a/b", "-x", ".hidden", "tab\\there"}) {
        const std::string cfg = dir.file("cfg.toml");
        writeFile(cfg, "[run]\nname = \"" + name + "\"\n[grammar]\nfile = \"" + sourcePath("grammars/spaceship.grammar") +
                           "\"\n[target]\nfill = \"" + sourcePath("targets/spaceship-reachable.vdb") +
                           "\"\n[ga]\npopulation = 10\ngenerations = 1\nelitism = 2\ntournament = 3\n");
        const auto r = runCommand("cd '" + dir.file("cwd") + "' && " + SHAPEVO_BIN + " run " + cfg + " -q");
        EXPECT_EQ(r.exitCode, 2) << name << ": " << r.output;
        EXPECT_NE(r.output.find("shapevo: error: " + cfg + ":2:8: run.name = \""), std::string::npos) << name << ": " << r.output;
        EXPECT_NE(r.output.find("must be a plain name"), std::string::npos) << name << ": " << r.output;
        EXPECT_EQ(entries(dir.file("cwd/runs")), 0u) << name;
        EXPECT_EQ(entries(dir.file("cwd")), 0u) << name << ": nothing created next to runs/ either";
        EXPECT_FALSE(fs::exists(dir.path().parent_path() / "evil")) << name;
    }
}

class OutputExtension : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        run_ = new TempDir;
        const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --out " + run_->file("r") +
                                  " --set ga.population=10 --set ga.generations=2 --set ga.elitism=2 --set ga.tournament=3 -q");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    static void TearDownTestSuite() {
        delete run_;
        run_ = nullptr;
    }
    static void expectRefused(const std::string& args, const std::string& message, const std::string& notCreated) {
        const auto r = runShapevo(args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.output;
        EXPECT_NE(r.output.find("shapevo: error: " + message), std::string::npos) << args << ": " << r.output;
        EXPECT_FALSE(fs::exists(notCreated)) << notCreated;
    }
    static TempDir* run_;
};
TempDir* OutputExtension::run_ = nullptr;

TEST_F(OutputExtension, ExportNeedsAModelVolumeOrImageExtension) {
    TempDir dir;
    const std::string run = run_->file("r");
    const std::string accepted = "-o takes a .obj, .ply, .glb, .vdb, .png or .svg file";
    expectRefused("export " + run + " --best -o " + dir.file("out/noext"),
                  dir.file("out/noext") + ": has no file extension; " + accepted, dir.file("out"));
    expectRefused("export " + run + " --best -o " + dir.file("x.foo"),
                  dir.file("x.foo") + ": unknown output extension '.foo'; " + accepted, dir.file("x.foo"));
    expectRefused("export " + run + " --best -o " + dir.file("x.obj") + " --format png",
                  dir.file("x.obj") + ": --format png does not match the file's extension .obj", dir.file("x.obj"));
    const auto ok = runShapevo("export " + run + " --best -o " + dir.file("m.PLY"));
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
}

TEST_F(OutputExtension, SampleNeedsAMeshExtensionAndAGenomeFileExtension) {
    TempDir dir;
    const std::string grammar = sourcePath("grammars/spaceship.grammar");
    expectRefused("sample " + grammar + " -o " + dir.file("x.foo"),
                  dir.file("x.foo") + ": unknown output extension '.foo'; -o takes a .obj, .ply, .glb or .png file", dir.file("x.foo"));
    expectRefused("sample " + grammar + " -o " + dir.file("noext"), dir.file("noext") + ": has no file extension", dir.file("noext"));
    expectRefused("sample " + grammar + " -o " + dir.file("m.obj") + " --genome " + dir.file("m.gen"),
                  dir.file("m.gen") + ": unknown output extension '.gen'; --genome takes a .genome file", dir.file("m.obj"));
}

TEST_F(OutputExtension, TargetWritesOnlyVdbFiles) {
    TempDir dir;
    const std::string mesh = sourcePath("targets/spaceship-reachable.obj");
    expectRefused("target " + mesh + " -o " + dir.file("x.obj"),
                  dir.file("x.obj") + ": unknown output extension '.obj'; -o takes a .vdb file", dir.file("x.obj"));
    expectRefused("target " + mesh + " -o " + dir.file("noext"), dir.file("noext") + ": has no file extension; -o takes a .vdb file",
                  dir.file("noext"));
}

}  // namespace
}  // namespace shapevo
