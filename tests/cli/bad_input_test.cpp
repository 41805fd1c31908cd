// Bad input end to end: every malformed or missing file gives one clear message naming the file
// (and the place where there is one), exit code 2, and nothing already written is touched.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

/// A minimal valid config in `dir` using the shipped grammar and reachable target.
std::string validConfig(const TempDir& dir, const std::string& extra = "") {
    const std::string path = dir.file("ok.toml");
    writeFile(path, "[grammar]\nfile = \"" + sourcePath("grammars/spaceship.grammar") + "\"\n[target]\nfill = \"" +
                        sourcePath("targets/spaceship-reachable.vdb") + "\"\n[ga]\npopulation = 10\ngenerations = 2\nelitism = 2\ntournament = 3\n" +
                        extra);
    return path;
}

void expectInputError(const test::CommandResult& r, const std::string& fragment) {
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << r.output;
    EXPECT_NE(r.output.find("shapevo: error: "), std::string::npos) << r.output;
}

TEST(BadInput, MissingConfigNamesTheFile) {
    TempDir dir;
    expectInputError(runShapevo("run " + dir.file("nope.toml") + " -q"), dir.file("nope.toml") + ": cannot open config file");
}

TEST(BadInput, MalformedTomlNamesLineAndColumn) {
    TempDir dir;
    writeFile(dir.file("bad.toml"), "[ga]\npopulation = = 3\n");
    expectInputError(runShapevo("run " + dir.file("bad.toml") + " -q"), dir.file("bad.toml") + ":2:");
}

TEST(BadInput, UnknownConfigKeyIsRejectedWithItsPlace) {
    TempDir dir;
    const std::string cfg = validConfig(dir, "populaton = 5\n");
    expectInputError(runShapevo("run " + cfg + " -q"), "ok.toml:10:1: unknown key 'populaton' in [ga]");
}

TEST(BadInput, OutOfRangeConfigValueIsRejected) {
    TempDir dir;
    expectInputError(runShapevo("run " + validConfig(dir, "mutation = 1.5\n") + " -q"), "ga.mutation = 1.5 is out of range [0, 1]");
}

TEST(BadInput, BadSetOverrideIsRejected) {
    TempDir dir;
    expectInputError(runShapevo("run " + validConfig(dir) + " --set population -q"), "--set:population: expected key=value");
}

TEST(BadInput, BadSetValuesNameTheOptionNotTheConfigFile) {
    TempDir dir;
    const std::string cfg = validConfig(dir);
    expectInputError(runShapevo("run " + cfg + " --set ga.population='\"many\"' -q"), "--set: ga.population must be a number");
    expectInputError(runShapevo("run " + cfg + " --set ga.popsize=3 -q"), "--set: unknown key 'popsize' in [ga]");
    expectInputError(runShapevo("run " + cfg + " --set gaa.population=3 -q"), "--set: unknown section [gaa]");
}

TEST(BadInput, MaxGenesBelowTheMandatorySubtreeIsRejected) {
    TempDir dir;
    writeFile(dir.file("m.grammar"), "start S\nrule S { box child B max 3 }\nrule B { box }\n");  // always 4 genes
    writeFile(dir.file("m.toml"), "[grammar]\nfile = \"m.grammar\"\n[target]\nfill = \"" +
                                      sourcePath("targets/spaceship-reachable.vdb") + "\"\n[genome]\nmax_genes = 3\n");
    expectInputError(runShapevo("run " + dir.file("m.toml") + " -q --out " + dir.file("out")), "is smaller than the 4 genes");
    EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
    expectInputError(runShapevo("sample " + dir.file("m.grammar") + " --max-genes 2 -o " + dir.file("m.obj")), "--max-genes");
}

TEST(BadInput, AGenomeFileThatIsNotOneIsRejectedQuickly) {
    TempDir dir;
    writeFile(dir.file("zeros.genome"), std::string(4096, '\0'));
    expectInputError(runShapevo("evaluate " + sourcePath("configs/spaceship.toml") + " " + dir.file("zeros.genome")), "bad magic");
}

TEST(BadInput, UnknownCommandLineOptionExitsWithTwo) {
    const auto r = runShapevo("run --frobnicate x.toml");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

TEST(BadInput, MissingGrammarFileIsNamed) {
    TempDir dir;
    writeFile(dir.file("g.toml"), "[grammar]\nfile = \"missing.grammar\"\n[target]\nfill = \"" +
                                      sourcePath("targets/spaceship-reachable.vdb") + "\"\n");
    expectInputError(runShapevo("run " + dir.file("g.toml") + " -q"), dir.file("missing.grammar") + ": cannot open grammar file");
}

TEST(BadInput, MalformedGrammarNamesLineAndColumn) {
    TempDir dir;
    writeFile(dir.file("bad.grammar"), "start S\nrule S {\n  box\n  child Q\n}\n");
    writeFile(dir.file("g.toml"), "[grammar]\nfile = \"bad.grammar\"\n[target]\nfill = \"" +
                                      sourcePath("targets/spaceship-reachable.vdb") + "\"\n");
    expectInputError(runShapevo("run " + dir.file("g.toml") + " -q"), dir.file("bad.grammar") + ":4:9: rule 'Q' is not defined");
}

TEST(BadInput, MissingAndNonVdbTargetsAreNamed) {
    TempDir dir;
    writeFile(dir.file("fake.vdb"), "this is not a volume");
    for (const std::string& target : {dir.file("missing.vdb"), dir.file("fake.vdb")}) {
        writeFile(dir.file("t.toml"), "[grammar]\nfile = \"" + sourcePath("grammars/spaceship.grammar") +
                                          "\"\n[target]\nfill = \"" + target + "\"\n");
        expectInputError(runShapevo("run " + dir.file("t.toml") + " -q"), target);
    }
    EXPECT_FALSE(std::filesystem::exists("runs/run")) << "a failed run must not create its output folder";
}

TEST(BadInput, ExistingOutputFolderIsNeverOverwritten) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("out"));
    writeFile(dir.file("out/precious.txt"), "keep me");
    expectInputError(runShapevo("run " + validConfig(dir) + " --out " + dir.file("out") + " -q"), "output folder already exists");
    EXPECT_EQ(readFile(dir.file("out/precious.txt")), "keep me");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.file("out")), {}), 1);
}

TEST(BadInput, MeshProblemsAreNamedForTheTargetCommand) {
    TempDir dir;
    writeFile(dir.file("empty.obj"), "# nothing here\n");
    writeFile(dir.file("open.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");  // a lone triangle: no inside
    writeFile(dir.file("garbage.obj"), "v 0 0 zero\n");
    expectInputError(runShapevo("target " + dir.file("missing.obj") + " -o " + dir.file("a.vdb")), dir.file("missing.obj"));
    expectInputError(runShapevo("target " + dir.file("empty.obj") + " -o " + dir.file("b.vdb")), dir.file("empty.obj"));
    expectInputError(runShapevo("target " + dir.file("open.obj") + " -o " + dir.file("c.vdb")), "cannot be determined");
    expectInputError(runShapevo("target " + dir.file("garbage.obj") + " -o " + dir.file("d.vdb")), dir.file("garbage.obj") + ":1");
    for (const char* f : {"a.vdb", "b.vdb", "c.vdb", "d.vdb"}) EXPECT_FALSE(std::filesystem::exists(dir.file(f)));
}

TEST(BadInput, ExistingTargetFileIsNotOverwritten) {
    TempDir dir;
    writeFile(dir.file("taken.vdb"), "mine");
    expectInputError(runShapevo("target " + sourcePath("targets/spaceship-reachable.obj") + " -o " + dir.file("taken.vdb")),
                     dir.file("taken.vdb"));
    EXPECT_EQ(readFile(dir.file("taken.vdb")), "mine");
}

TEST(BadInput, CorruptGenomeIsRejectedByEvaluate) {
    TempDir dir;
    std::string bytes = readFile(sourcePath("targets/spaceship-reachable.genome"));
    ASSERT_GT(bytes.size(), 40u);
    writeFile(dir.file("short.genome"), bytes.substr(0, bytes.size() - 4));
    bytes[40] ^= 0x7f;  // damage a word of the first gene
    writeFile(dir.file("flipped.genome"), bytes);
    const std::string cfg = sourcePath("configs/spaceship.toml");
    expectInputError(runShapevo("evaluate " + cfg + " " + dir.file("short.genome")), dir.file("short.genome"));
    expectInputError(runShapevo("evaluate " + cfg + " " + dir.file("flipped.genome")), "invalid chromosome");
}

}  // namespace
}  // namespace shapevo
