// run/config_file checks from issue 11: run.name is a plain name; run.seed is read exactly up to
// TOML's largest integer; initial_genes_max may not exceed genome.max_genes; a rule broken by an
// override is blamed on --set; a config path that is a folder says so; quoted values are cut.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "run/config_file.hpp"

namespace shapevo {
namespace {

const std::string kVolume = "[grammar]\nfile = \"g.grammar\"\n[target]\nfill = \"t.vdb\"\n";

InputError errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        parseConfig(text, "x.toml", overrides);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return InputError("", "", "");
}

TEST(ConfigChecks, RunNameIsAPlainFolderName) {
    for (const std::string bad : {"../../evil", "", ".", "..", "a/b", "a\\\\b", "-rf", ".hidden", "new\\nline"}) {
        const InputError e = errorOf("[run]\nname = \"" + bad + "\"\n" + kVolume);
        EXPECT_EQ(e.file(), "x.toml") << bad;
        EXPECT_EQ(e.where(), "2:8") << bad;
        EXPECT_NE(e.message().find("run.name = \""), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("must be a plain name"), std::string::npos) << e.what();
    }
    EXPECT_EQ(errorOf(kVolume, {"run.name=\"a/b\""}).file(), "--set");
    EXPECT_NE(std::string(errorOf("[run]\nname = \"" + std::string(129, 'n') + "\"\n" + kVolume).what()).find("129 bytes long"),
              std::string::npos);
    for (const std::string& good : std::vector<std::string>{"run", "spaceship-2", "my run", "a..b", "tree_v1.5", std::string(128, 'n')})
        EXPECT_EQ(parseConfig("[run]\nname = \"" + good + "\"\n" + kVolume, "x.toml").name, good);
}

TEST(ConfigChecks, SeedIsReadExactlyUpToTheLargestTomlInteger) {
    EXPECT_EQ(parseConfig("[run]\nseed = 9223372036854775807\n" + kVolume, "x.toml").seed, 9223372036854775807u);
    EXPECT_EQ(parseConfig("[run]\nseed = 9007199254740993\n" + kVolume, "x.toml").seed, 9007199254740993u) << "2^53 + 1, exactly";
    EXPECT_EQ(parseConfig(kVolume, "x.toml", {"run.seed=99"}).seed, 99u);
    EXPECT_NE(std::string(errorOf("[run]\nseed = -1\n" + kVolume).what()).find("x.toml:2:8: run.seed = -1 is out of range"),
              std::string::npos);
    EXPECT_NE(std::string(errorOf("[run]\nseed = 1.5\n" + kVolume).what()).find("run.seed must be a whole number"), std::string::npos);
}

TEST(ConfigChecks, InitialGenesMaxAboveMaxGenesNamesBothKeys) {
    const InputError e = errorOf(kVolume + "[genome]\nmax_genes = 30\n[ga]\ninitial_genes_max = 50\n");
    EXPECT_EQ(e.where(), "8:21");
    EXPECT_NE(e.message().find("ga.initial_genes_max = 50 exceeds genome.max_genes = 30"), std::string::npos) << e.what();
    EXPECT_EQ(errorOf(kVolume + "[ga]\ninitial_genes_max = 50\n", {"genome.max_genes=30"}).file(), "--set");
    // the default initial_genes_max (40) is not an error with a smaller max_genes
    EXPECT_EQ(parseConfig(kVolume + "[genome]\nmax_genes = 30\n", "x.toml").limits.maxGenes, 30u);
    EXPECT_EQ(parseConfig(kVolume + "[genome]\nmax_genes = 50\n[ga]\ninitial_genes_max = 50\n", "x.toml").population.initialGenesMax, 50u);
}

TEST(ConfigChecks, ARuleBrokenByAnOverrideIsBlamedOnTheSet) {
    const std::string text = kVolume + "[ga]\npopulation = 40\nelitism = 10\n";
    const InputError fromSet = errorOf(text, {"ga.elitism=40"});
    EXPECT_EQ(fromSet.file(), "--set");
    EXPECT_NE(fromSet.message().find("ga.elitism = 40, ga.population = 40"), std::string::npos) << fromSet.what();
    const InputError fromFile = errorOf(kVolume + "[ga]\npopulation = 40\nelitism = 40\n");
    EXPECT_EQ(fromFile.file(), "x.toml");
    EXPECT_EQ(fromFile.where(), "7:11") << "the later of the two keys";
    EXPECT_EQ(errorOf(kVolume, {"score.length_max=10"}).file(), "--set");
    EXPECT_EQ(errorOf(kVolume, {"migration.count=300"}).file(), "--set");
    EXPECT_EQ(errorOf(kVolume, {"target.grid_min=[0.0,0.0,0.0]"}).file(), "--set");
}

TEST(ConfigChecks, AConfigPathThatIsAFolderSaysSo) {
    test::TempDir dir;
    try {
        loadConfig(dir.path().string());
        FAIL() << "accepted a folder";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.path().string());
        EXPECT_NE(e.message().find("is a folder, not a config file"), std::string::npos) << e.what();
    }
}

TEST(ConfigChecks, ValuesQuotedInMessagesAreCutTo80Characters) {
    const std::string huge(1'000'000, 'q');
    for (const std::string& text : std::vector<std::string>{kVolume + "[search]\nmethod = \"" + huge + "\"\n", kVolume + "[score]\nform = \"" + huge + "\"\n",
                                    kVolume + "[ga]\n" + huge + " = 1\n", kVolume + "[" + huge + "]\n",
                                    kVolume + "[ga]\npopulation = \"" + huge + "\"\n"}) {
        const std::string what = errorOf(text).what();
        EXPECT_LT(what.size(), 400u) << what.substr(0, 500);
        EXPECT_NE(what.find(std::string(80, 'q') + "\u2026"), std::string::npos) << what.substr(0, 500);
    }
}

}  // namespace
}  // namespace shapevo
