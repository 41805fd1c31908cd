// A recursive stochastic rule (castlemaker-crl.txt §5.2: "this might result in an incredibly
// large number of recursions") end to end: `shapevo sample` stops every derivation at
// --max-genes and every model at genome.max_primitives, and when no draw fits it exits 2 with a
// message naming the limit and §5.2 (never a hang or a crash, nothing written); `shapevo run`
// evolves such a rule file, its genes grown one at a time within genome.max_genes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::runShapevo;
using test::TempDir;
using test::writeFile;

namespace fs = std::filesystem;

const std::string kLot = "L = rect(0, 0, 10, 10);\nL -> extrude(1) {A};\n";
/// The thesis's own example: ends after 5 steps on average.
const std::string kEnds = kLot + "A -> [0.8] insert_volume(1,1,1,0,0,1){A}, [0.2] insert_volume(1,1,1,1,1,1);\n";
/// Never ends: the only alternative recurses.
const std::string kNeverEnds = kLot + "A -> [1] insert_volume(1,1,1,0,0,1){A};\n";
/// Branches into four recursions at every step (each corner), 0.9 of the time.
const std::string kBranches = kLot + "A -> [0.9] corners(0.5,0.5,1,1,1,1){A}, [0.1] insert_volume(1,1,1,1,1,1);\n";
/// Few genes, but every step repeats the rest 100 times: 4 steps make a million primitives.
const std::string kMultiplies = kLot + "A -> [0.5] edges(0.1, 0.1, 100, 0, 0, 0) {A}, [0.5] insert_volume(1, 1, 1, 1, 1, 1);\n";

const std::string kNeverEndsNote = "a recursive stochastic rule may never end (castlemaker-crl.txt §5.2)";

TEST(RuleRecursion, TheThesisExampleSamplesAndEnds) {
    TempDir dir;
    writeFile(dir.file("a.rule"), kEnds);
    const auto r = runShapevo("sample " + dir.file("a.rule") + " --seed 1 --count 20 -o " + dir.file("m.obj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir.file("m-020.obj")));
}

TEST(RuleRecursion, ARecursionThatNeverEndsStopsAtMaxGenesWithAClearMessage) {
    TempDir dir;
    writeFile(dir.file("a.rule"), kNeverEnds);
    const auto r = runShapevo("sample " + dir.file("a.rule") + " --seed 3 -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(r.output, "shapevo: error: --max-genes: all 10000 derivations of " + dir.file("a.rule") +
                            " drawn (seed 3) grew past the limit of 100 genes and were stopped there; " + kNeverEndsNote +
                            ": lower the probabilities of the alternatives that recurse, or raise --max-genes\n");
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
}

TEST(RuleRecursion, ABranchingRecursionEndsOnlyBySmallDraws) {
    TempDir dir;
    writeFile(dir.file("a.rule"), kBranches);
    // Only the draws that end early fit under --max-genes: sample keeps one of them ...
    const auto small = runShapevo("sample " + dir.file("a.rule") + " --seed 1 -o " + dir.file("m.obj"));
    ASSERT_EQ(small.exitCode, 0) << small.output;
    // ... and a window above them says which limit stopped the others, and why.
    const auto r = runShapevo("sample " + dir.file("a.rule") + " --seed 1 --min-genes 30 -o " + dir.file("n.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: --min-genes/--max-genes: no derivation of " + dir.file("a.rule") +
                            " with 30 to 100 genes in 10000 draws (seed 1; "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" of them grew past --max-genes); the grammar's prob values make that size rare or impossible (" +
                            kNeverEndsNote + "): widen the window\n"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir.file("n.obj")));
}

TEST(RuleRecursion, AModelPastThePrimitiveLimitIsRefusedNamingIt) {
    TempDir dir;
    writeFile(dir.file("a.rule"), kMultiplies);
    // Seeds 1 to 20: some derivation recurses 4 times or more (seed 10 does, with 6 genes).
    const auto r = runShapevo("sample " + dir.file("a.rule") + " --seed 1 --count 20 -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("shapevo: error: genome.max_primitives: the derivation of " + dir.file("a.rule") + " drawn with seed "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" genes) reached the limit of 262144 primitives (the limit genome.max_primitives sets; sample uses its "
                            "default) and was stopped there; " +
                            kNeverEndsNote + ": lower the probabilities of the alternatives that recurse, or --max-genes\n"),
              std::string::npos)
        << r.output;
    for (int k = 1; k <= 20; ++k) EXPECT_FALSE(fs::exists(dir.file("m-" + std::string(k < 10 ? "00" : "0") + std::to_string(k) + ".obj"))) << k;
}

TEST(RuleRecursion, AnOptionalRecursionOfAGrammarGetsTheSameNote) {
    TempDir dir;
    writeFile(dir.file("a.grammar"), "start A\nrule A { box child A optional }\n");
    const auto r = runShapevo("sample " + dir.file("a.grammar") + " --max-genes 20 -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--max-genes: all 10000 derivations of " + dir.file("a.grammar") +
                            " drawn (seed 1) grew past the limit of 20 genes and were stopped there; " + kNeverEndsNote),
              std::string::npos)
        << r.output;
    // A window no draw meets without any runaway recursion keeps the plain message.
    writeFile(dir.file("b.grammar"), "start A\nrule A { box child B prob 0.5 }\nrule B { box }\n");
    const auto plain = runShapevo("sample " + dir.file("b.grammar") + " --min-genes 3 -o " + dir.file("m.obj"));
    EXPECT_EQ(plain.exitCode, 2) << plain.output;
    EXPECT_EQ(plain.output, "shapevo: error: --min-genes/--max-genes: no derivation of " + dir.file("b.grammar") +
                                " with 3 to 100 genes in 10000 draws (seed 1); the grammar's prob values make that size rare or "
                                "impossible: widen the window\n");
}

TEST(RuleRecursion, APlainGrammarPastThePrimitiveLimitIsRefusedWithoutTheNote) {
    TempDir dir;
    writeFile(dir.file("a.grammar"), "start A\nrule A { repeat x count 100 { repeat y count 100 { repeat z count 100 { box } } } }\n");
    const auto r = runShapevo("sample " + dir.file("a.grammar") + " -o " + dir.file("m.obj"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(r.output, "shapevo: error: genome.max_primitives: the derivation of " + dir.file("a.grammar") +
                            " drawn with seed 1 (1 gene) reached the limit of 262144 primitives (the limit genome.max_primitives "
                            "sets; sample uses its default) and was stopped there; nested splits, repeats, comps and mirrors "
                            "multiply what they hold: nest fewer of them\n");
    EXPECT_FALSE(fs::exists(dir.file("m.obj")));
}

TEST(RuleRecursion, RunEvolvesRuleFilesThatMayNeverEnd) {
    const std::string kSmall = " --set ga.population=30 --set ga.elitism=4 --set ga.tournament=5 --set ga.generations=6 -q";
    const std::vector<std::pair<std::string, std::string>> files = {{"ends", kEnds}, {"never", kNeverEnds}, {"branches", kBranches}};
    for (const auto& [name, text] : files) {
        TempDir dir;
        const std::string cfg = test::configWithGrammar(dir, text, name, ".rule");
        const auto r = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmall + " --set genome.max_genes=40");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.output;
        EXPECT_TRUE(fs::exists(dir.file("run/best.obj"))) << name;
    }
    // The primitive limit is a config key there: models that reach it are scored on their first ones.
    TempDir dir;
    const std::string cfg = test::configWithGrammar(dir, kMultiplies, "multiplies", ".rule");
    const auto r = runShapevo("run " + cfg + " --out " + dir.file("run") + kSmall + " --set genome.max_primitives=2000");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("reached genome.max_primitives = 2000"), std::string::npos) << r.output;
    EXPECT_NE(readFile(dir.file("run/summary.json")).find("\"truncated_models\""), std::string::npos);
}

}  // namespace
}  // namespace shapevo
