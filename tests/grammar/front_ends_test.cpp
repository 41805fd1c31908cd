// The grammar front ends' table (grammar/front_ends.hpp): every entry is distinct and complete,
// a file goes to the entry of its extension (any other to the shapevo language, as before),
// `shapevo translate` translates through the table and refuses a file that needs no translation
// naming the front ends that translate, and a translation's errors stay in the user's own file.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/translation.hpp"

namespace shapevo {
namespace {

using test::sourcePath;
using test::TempDir;
using test::writeFile;

/// The what() of the InputError `f` throws ("" if it throws none).
template <class F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FrontEnds, EveryEntryHasAUniqueExtensionAndNameAndIsComplete) {
    std::set<std::string_view> extensions, names;
    ASSERT_GE(grammarFrontEnds().size(), 2u);
    for (const GrammarFrontEnd& e : grammarFrontEnds()) {
        EXPECT_TRUE(extensions.insert(e.extension).second) << e.extension;
        EXPECT_TRUE(names.insert(e.name).second) << e.name;
        ASSERT_GE(e.extension.size(), 2u);
        EXPECT_EQ(e.extension[0], '.') << e.extension;
        EXPECT_FALSE(e.summary.empty()) << e.name;
        EXPECT_FALSE(e.fileNoun.empty()) << e.name;
        EXPECT_NE(e.compile, nullptr) << e.name;
        EXPECT_EQ(findGrammarFrontEnd(e.extension), &e);
    }
    EXPECT_EQ(grammarFrontEnds().front().extension, ".grammar");  // the default comes first
}

TEST(FrontEnds, FoundByExtension) {
    ASSERT_NE(findGrammarFrontEnd(".rule"), nullptr);
    EXPECT_EQ(findGrammarFrontEnd(".rule")->name, "CastleMaker rule file");
    ASSERT_NE(findGrammarFrontEnd(".grammar"), nullptr);
    EXPECT_EQ(findGrammarFrontEnd(".grammar")->name, "shapevo grammar");
    EXPECT_EQ(findGrammarFrontEnd(".txt"), nullptr);
    EXPECT_EQ(findGrammarFrontEnd("rule"), nullptr);
    EXPECT_EQ(&grammarFrontEndFor("a/b.c/castle.rule"), findGrammarFrontEnd(".rule"));
    EXPECT_EQ(&grammarFrontEndFor("castle.grammar"), findGrammarFrontEnd(".grammar"));
    EXPECT_EQ(&grammarFrontEndFor("castle.rule.txt"), findGrammarFrontEnd(".grammar"));
    EXPECT_EQ(&grammarFrontEndFor("castle"), findGrammarFrontEnd(".grammar"));
}

TEST(FrontEnds, NamesForMessages) {
    EXPECT_EQ(grammarExtensions(), "\".grammar\", \".rule\" or \".pcg\"");
    EXPECT_EQ(translatingFrontEnds(), "a CastleMaker rule file (.rule) or a procedural content graph (.pcg)");
}

TEST(FrontEnds, OnlyRuleFilesHaveRecursionsThatEndOnlyByChance) {
    EXPECT_TRUE(grammarFrontEndFor("x.rule").recursionsEndOnlyByChance);
    EXPECT_FALSE(grammarFrontEndFor("x.grammar").recursionsEndOnlyByChance);
    EXPECT_FALSE(grammarFrontEndFor("x.txt").recursionsEndOnlyByChance);
}

TEST(FrontEnds, OnlyRuleAndGraphFilesTranslate) {
    EXPECT_NE(grammarFrontEndFor("x.rule").translate, nullptr);
    EXPECT_NE(grammarFrontEndFor("x.pcg").translate, nullptr);
    EXPECT_EQ(grammarFrontEndFor("x.grammar").translate, nullptr);
}

// Unknown extensions were always read as the shapevo language (a config or a checkpoint may name
// such a file); the table keeps that, and errors name the file that was read.
TEST(FrontEnds, AnyOtherExtensionIsReadAsTheShapevoLanguage) {
    TempDir dir;
    writeFile(dir.file("good.txt"), "start A\nrule A { box }\n");
    EXPECT_EQ(loadGrammar(dir.file("good.txt")).rules.size(), 1u);
    writeFile(dir.file("bad.txt"), "start A\nrule A {\n  rotate q 3\n}\n");
    EXPECT_EQ(inputErrorOf([&] { loadGrammar(dir.file("bad.txt")); }).rfind(dir.file("bad.txt") + ":3:10: ", 0), 0u);
    EXPECT_EQ(inputErrorOf([&] { loadGrammar(dir.file("none.txt")); }), dir.file("none.txt") + ": cannot open grammar file");
    EXPECT_EQ(inputErrorOf([&] { loadGrammar(dir.file("none.rule")); }), dir.file("none.rule") + ": cannot open rule file");
}

TEST(FrontEnds, RuleFilesCompileThroughTheTable) {
    const std::string path = sourcePath("grammars/castlemaker/toy-castle.rule");
    const Grammar g = loadGrammar(path);
    EXPECT_GT(g.rules.size(), 1u);
    EXPECT_EQ(g.source, test::readFile(path));  // the rule file's text, not its translation
}

TEST(TranslateGrammarFile, TranslatesARuleFile) {
    const std::string path = sourcePath("grammars/castlemaker/toy-castle.rule");
    const std::string out = translateGrammarFile(path);
    EXPECT_EQ(out.rfind("# " + path + " in the shapevo language", 0), 0u) << out;
    EXPECT_NE(out.find("\nrule "), std::string::npos) << out;
    EXPECT_NE(out.find("# toy-castle.rule:"), std::string::npos) << out;
    EXPECT_NE(out.find("\nstart "), std::string::npos) << out;
}

TEST(TranslateGrammarFile, TakesAttrOverrides) {
    TempDir dir;
    writeFile(dir.file("a.rule"), "attr h = 2;\nL = rect(0, 0, 1, 1);\nL -> extrude(h) {A};\nA -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    EXPECT_NO_THROW(translateGrammarFile(dir.file("a.rule"), {{"h", 7}}));
    EXPECT_THROW(translateGrammarFile(dir.file("a.rule"), {{"nope", 7}}), InputError);  // an attr it does not define
}

TEST(TranslateGrammarFile, RefusesAFileThatNeedsNoTranslation) {
    const std::string path = sourcePath("grammars/castle.grammar");
    EXPECT_EQ(inputErrorOf([&] { translateGrammarFile(path); }),
              path + ": is read as a shapevo grammar, which needs no translation; shapevo translate reads a CastleMaker rule file (.rule) or a procedural content graph (.pcg)");
    EXPECT_EQ(inputErrorOf([&] { translateGrammarFile("missing.txt"); }),
              "missing.txt: is read as a shapevo grammar, which needs no translation; shapevo translate reads a CastleMaker rule file (.rule) or a procedural content graph (.pcg)");
    EXPECT_EQ(inputErrorOf([&] { translateGrammarFile("missing.rule"); }), "missing.rule: cannot open rule file");
}

// A problem the rule-file reader finds, and one only the parse of its translation finds, are both
// reported at the rule file's line:column.
TEST(TranslateGrammarFile, ErrorsAreLocatedInTheRuleFile) {
    TempDir dir;
    writeFile(dir.file("bad.rule"), "L = rect(0, 0, 1, 1);\nL -> extrude(2) {Missing};\n");
    EXPECT_EQ(inputErrorOf([&] { translateGrammarFile(dir.file("bad.rule")); }).rfind(dir.file("bad.rule") + ":2:18: handle 'Missing'", 0), 0u);
    writeFile(dir.file("main.rule"), "L = rect(0, 0, 1, 1);\nL -> add_texture(\"stone\", \"stone.png\", 2, 1) {A};\n"
                                     "A -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    writeFile(dir.file("stone.png"), "png");
    const std::string expected = dir.file("main.rule") + ":2:6: texture 'stone.png' is not a PNG";
    EXPECT_EQ(inputErrorOf([&] { translateGrammarFile(dir.file("main.rule")); }).rfind(expected, 0), 0u);
    EXPECT_EQ(inputErrorOf([&] { loadGrammar(dir.file("main.rule")); }).rfind(expected, 0), 0u);
}

// Any front end that translates gets this: a parse error of the translated text names the place
// its origin map gives for the offending line, in the user's own file.
TEST(CompileTranslation, ReportsTheTranslatedTextsErrorsAtTheirOrigin) {
    Translation t;
    t.text = "start A\nrule A {\n  rotate q 3\n}\n";
    t.origin = {{"street.pcg", 1, 1}, {"street.pcg", 4, 2}, {"street.pcg", 7, 5}, {"street.pcg", 4, 2}};
    t.files = {"lamp.pcg"};
    EXPECT_EQ(inputErrorOf([&] { compileTranslation(t, "graph text", "/x/street.pcg", {}); }).rfind("street.pcg:7:5: ", 0), 0u);
    t.text = "start A\nrule A {\n  box\n}\n";
    const Grammar g = compileTranslation(t, "graph text", "/x/street.pcg", {});
    EXPECT_EQ(g.source, "graph text");
    EXPECT_EQ(g.includes, std::vector<std::string>{"lamp.pcg"});
    EXPECT_EQ(g.path, "/x/street.pcg");
}

}  // namespace
}  // namespace shapevo
