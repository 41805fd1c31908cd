// Messages that say what is wrong and where (issue 11, row 13): a truncated VDB says so, a config
// path that is a folder says so, a rule broken by --set is blamed on --set, a huge bad string is
// cut short, and warnings go to stderr, never to stdout.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runCommand;
using test::runShapevo;
using test::sourcePath;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

const std::string kSmallMessages = " --set ga.population=10 --set ga.generations=2 --set ga.elitism=2 --set ga.tournament=3 -q";

void expectErrorSaying(const test::CommandResult& r, const std::string& fragment) {
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: " + fragment), std::string::npos) << "expected '" << fragment << "' in: " << r.output;
}

TEST(Messages, ATruncatedTargetSaysItIsTruncated) {
    TempDir dir;
    const std::string whole = readFile(sourcePath("targets/spaceship-reachable.vdb"));
    for (const std::size_t bytes : {std::size_t(10), std::size_t(100), whole.size() / 2}) {
        const std::string vdb = dir.file("cut-" + std::to_string(bytes) + ".vdb");
        writeFile(vdb, whole.substr(0, bytes));
        const auto r = runShapevo("run " + sourcePath("configs/spaceship.toml") + " --set target.fill='\"" + vdb + "\"' --out " +
                                  dir.file("out") + kSmallMessages);
        expectErrorSaying(r, vdb + ": ");
        EXPECT_NE(r.output.find("truncated or unreadable"), std::string::npos) << bytes << ": " << r.output;
        EXPECT_EQ(r.output.find("no float grid"), std::string::npos) << bytes << ": " << r.output;
        EXPECT_LT(r.output.size(), 400u) << bytes << ": " << r.output;
        EXPECT_FALSE(fs::exists(dir.file("out")));
    }
}

TEST(Messages, AConfigPathThatIsAFolderSaysItIsAFolder) {
    TempDir dir;
    fs::create_directories(dir.file("configs"));
    const auto r = runShapevo("run " + dir.file("configs") + " -q");
    expectErrorSaying(r, dir.file("configs") + ": is a folder, not a config file");
    EXPECT_EQ(r.output.find("missing [grammar]"), std::string::npos) << r.output;
    expectErrorSaying(runShapevo("evaluate " + dir.file("configs") + " " + sourcePath("targets/spaceship-reachable.genome")),
                     dir.file("configs") + ": is a folder");
}

TEST(Messages, ARuleBrokenByASetIsBlamedOnTheSetNotOnTheFile) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/spaceship.toml");  // elitism = 30
    expectErrorSaying(runShapevo("run " + cfg + " --set ga.population=20 --out " + dir.file("a") + " -q"),
                     "--set: elitism must be smaller than population (ga.elitism = 30, ga.population = 20)");
    expectErrorSaying(runShapevo("run " + cfg + " --set score.length_max=10 --out " + dir.file("a") + " -q"),
                     "--set: length_max must be greater than length_optimal");
    expectErrorSaying(runShapevo("run " + sourcePath("configs/tree-sketch.toml") + " --set camera.fov_degrees=180 --out " +
                                dir.file("a") + " -q"),
                     "--set:camera.fov_degrees: ");
    // the same rule broken in the file names the file's line
    writeFile(dir.file("c.toml"), "[grammar]\nfile = \"" + sourcePath("grammars/spaceship.grammar") + "\"\n[target]\nfill = \"" +
                                      sourcePath("targets/spaceship-reachable.vdb") + "\"\n[ga]\npopulation = 20\n");
    expectErrorSaying(runShapevo("run " + dir.file("c.toml") + " --out " + dir.file("a") + " -q"),
                     dir.file("c.toml") + ":6:14: elitism must be smaller than population");
    EXPECT_FALSE(fs::exists(dir.file("a")));
}

TEST(Messages, AHugeBadStringIsCutShort) {
    TempDir dir;
    const std::string huge(50'000'000, 'x');
    const std::string head = "[grammar]\nfile = \"" + sourcePath("grammars/spaceship.grammar") + "\"\n[target]\nfill = \"" +
                             sourcePath("targets/spaceship-reachable.vdb") + "\"\n";
    writeFile(dir.file("method.toml"), head + "[search]\nmethod = \"" + huge + "\"\n");
    writeFile(dir.file("key.toml"), head + "[ga]\n" + huge + " = 1\n");
    writeFile(dir.file("name.toml"), "[run]\nname = \"" + huge + "\"\n" + head);
    writeFile(dir.file("path.toml"), "[grammar]\nfile = \"" + huge + "\"\n[target]\nfill = \"" +
                                         sourcePath("targets/spaceship-reachable.vdb") + "\"\n");
    for (const char* f : {"method.toml", "key.toml", "name.toml", "path.toml"}) {
        const auto r = runShapevo("run " + dir.file(f) + " -q --out " + dir.file("out"));
        EXPECT_EQ(r.exitCode, 2) << f;
        EXPECT_LT(r.output.size(), 700u) << f << ": " << r.output.substr(0, 2000);
        EXPECT_NE(r.output.find(std::string(80, 'x') + "\u2026"), std::string::npos) << f << ": " << r.output.substr(0, 2000);
        EXPECT_EQ(r.output.find(std::string(300, 'x')), std::string::npos) << f;
    }
    EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Messages, WarningsGoToStderrNeverToStdout) {
    TempDir dir;
    const std::string cfg = sourcePath("configs/spaceship.toml");
    ASSERT_EQ(runShapevo("run " + cfg + " --out " + dir.file("r") + " --set checkpoint.interval=1 --set checkpoint.keep=5" + kSmallMessages)
                  .exitCode,
              0);
    // damage the newest checkpoint: resume says so (a warning) and goes on from the one before
    std::string newest;
    for (const auto& e : fs::directory_iterator(dir.file("r")))
        if (e.path().filename().string().rfind("checkpoint-", 0) == 0 && e.path().string() > newest) newest = e.path().string();
    ASSERT_FALSE(newest.empty());
    writeFile(newest + "/island-0000.h5", "damaged");
    const std::string stderrFile = dir.file("stderr.txt");
    const auto r = runCommand("{ " + std::string(SHAPEVO_BIN) + " resume " + dir.file("r") + " --generations 4 2>" + stderrFile + "; }");
    const std::string err = readFile(stderrFile);
    ASSERT_EQ(r.exitCode, 0) << r.output << err;
    EXPECT_NE(err.find("shapevo: "), std::string::npos) << "the damaged checkpoint is reported on stderr: " << err;
    EXPECT_NE(r.output.find("gen 4/4"), std::string::npos) << "progress stays on stdout: " << r.output;
    for (std::size_t at = 0; at < r.output.size();) {  // no diagnostic line on stdout
        EXPECT_NE(r.output.compare(at, 9, "shapevo: "), 0) << r.output;
        const std::size_t nl = r.output.find('\n', at);
        at = nl == std::string::npos ? r.output.size() : nl + 1;
    }
}

}  // namespace
}  // namespace shapevo
