// The reference cannot drift: docs/reference/ (config.md, commands.md, shapevo.1) is exactly what
// `shapevo reference --write` makes from the code, the man page formats without a warning under
// `man -l`, and the config reference lists every key of every shipped config, each with a type
// and a meaning (run/config_reference.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "run/config_reference.hpp"

#include "../test_support.hpp"

namespace shapevo {
namespace {

std::string referenceFileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(ReferenceDocs, DocsReferenceIsWhatTheBinaryWrites) {
    const test::TempDir dir;
    const auto written = test::runShapevo("reference --write " + dir.path().string());
    ASSERT_EQ(written.exitCode, 0) << written.output;
    for (const char* name : {"config.md", "commands.md", "shapevo.1"}) {
        const std::string kept = test::sourcePath("docs/reference/") + name;
        ASSERT_TRUE(std::filesystem::exists(kept)) << kept;
        EXPECT_TRUE(referenceFileText(kept) == referenceFileText(dir.file(name)))
            << "docs/reference/" << name << " differs from what the binary writes; make it again with\n"
            << "  build/shapevo reference --write docs/reference\nand commit it";
    }
}

TEST(ReferenceDocs, ManPageFormatsWithoutWarnings) {
    if (test::runCommand("command -v man").exitCode != 0) GTEST_SKIP() << "man is not installed (Debian: man-db)";
    const std::string page = test::sourcePath("docs/reference/shapevo.1");
    // man's warnings (w: every kind groff has) go to stderr, the formatted page to /dev/null (in a subshell: runCommand
    // appends 2>&1, which would send both to /dev/null).
    const auto shown = test::runCommand("(MANWIDTH=100 man --warnings=w -l '" + page + "' 2>&1 >/dev/null)");
    EXPECT_EQ(shown.exitCode, 0) << shown.output;
    EXPECT_EQ(shown.output, "") << "man -l " << page << " warned";
    const auto text = test::runCommand("MANWIDTH=100 man -l '" + page + "' 2>/dev/null");
    EXPECT_NE(text.output.find("shapevo reference"), std::string::npos) << "the page lists every command";
    EXPECT_NE(text.output.find("population"), std::string::npos) << "the page lists the config keys";
}

TEST(ConfigReference, ListsEveryKeyOfEveryShippedConfig) {
    std::set<std::string> listed;
    for (const ReferenceKey& k : configReferenceKeys()) listed.insert(k.record.section + "." + k.record.key);
    int configs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("configs"))) {
        if (entry.path().extension() != ".toml") continue;
        ++configs;
        const toml::table root = toml::parse_file(entry.path().string());
        for (const auto& [section, table] : root)
            for (const auto& [key, value] : *table.as_table())
                EXPECT_TRUE(listed.count(std::string(section.str()) + "." + std::string(key.str())))
                    << entry.path().filename() << ": " << section.str() << "." << key.str() << " is not in the reference";
    }
    EXPECT_GT(configs, 5);
}

TEST(ConfigReference, EveryKeyHasATypeAMeaningAndOneEntry) {
    std::set<std::string> seen;
    const auto keys = configReferenceKeys();
    EXPECT_GT(keys.size(), 60u);
    for (const ReferenceKey& k : keys) {
        const std::string name = k.record.section + "." + k.record.key;
        EXPECT_TRUE(seen.insert(name).second) << name << " twice";
        EXPECT_FALSE(k.record.type.empty()) << name;
        EXPECT_GE(k.record.meaning.size(), 10u) << name << " has no meaning";
        EXPECT_FALSE(k.kinds.empty()) << name;
    }
    EXPECT_TRUE(seen.count("camera.eye") && seen.count("target.fill") && seen.count("search.hybrid_islands") &&
                seen.count("grammar.attr") && seen.count("run.seed"));
}

TEST(ConfigReference, MarkdownGivesEachKeysDefaultAndRange) {
    const std::string md = configReferenceMarkdown();
    EXPECT_NE(md.find("| `population` | whole number | `200` | [2, 1e+07] |"), std::string::npos) << md.substr(0, 2000);
    EXPECT_NE(md.find("## [camera]\n\nOnly with an image target."), std::string::npos);
    EXPECT_NE(md.find("| `method` | string | `\"hybrid\"` |"), std::string::npos);
}

}  // namespace
}  // namespace shapevo
