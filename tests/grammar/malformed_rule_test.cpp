// Every malformed CastleMaker rule file (.rule, castlemaker-crl.txt) is rejected with an
// InputError whose text is exactly `file:LINE:COLUMN: message`, the place being the rule file's
// own (never a line of its translation), and the message saying what is wrong. Files that name
// other files (includes, OBJs, textures, inserted rule files) are written to a temporary folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::TempDir;
using test::writeFile;

struct MalformedRule {
    const char* name;     ///< test name suffix: what is wrong
    std::string text;     ///< the rule file
    std::string where;    ///< expected "bad.rule:LINE:COL"
    std::string message;  ///< the expected message, exactly
};

std::ostream& operator<<(std::ostream& os, const MalformedRule& m) { return os << m.name; }

// Line 1 of most cases: a lot. The case's own line is line 2.
const std::string kLot = "L = rect(0, 0, 10, 10);\n";
const std::string kA = "A -> insert_volume(1, 1, 1, 0, 0, 1);\n";
std::string lotThen(const std::string& lines) { return kLot + lines; }

const char* kFunctionList =
    "rect, circ, center, corners, edges, lot_split, lot_split_simple, lot_split_rand, extrude, comp, subdiv, uniform_subdiv, "
    "repeat_subdiv, split, uniform_split, repeat_split, scale, translate, add_material, add_texture, insert, insert_volume, "
    "insert_cylinder, insert_cone, insert_parabolic_cone";

std::string chain(int handles) {  // L -> H0 -> H1 -> ... -> H<handles>, each one an extrude
    std::string s = lotThen("L -> extrude(1) {H0};\n");
    for (int i = 0; i < handles; ++i) s += "H" + std::to_string(i) + " -> extrude(1) {H" + std::to_string(i + 1) + "};\n";
    return s + "H" + std::to_string(handles) + " -> insert_volume(1, 1, 1, 0, 0, 1);\n";
}

const std::vector<MalformedRule>& ruleCases() {
    static const std::vector<MalformedRule> all = {
        // --- functions and their arguments ------------------------------------------------
        {"UnknownFunction", lotThen("L -> extrud(3) {A};\n" + kA), "bad.rule:2:6",
         std::string("unknown function 'extrud' (did you mean extrude?): expected one of ") + kFunctionList},
        {"UnknownFunctionUnlikeAny", lotThen("L -> make_tower(3) {A};\n" + kA), "bad.rule:2:6",
         std::string("unknown function 'make_tower': expected one of ") + kFunctionList},
        {"TooFewArguments", lotThen("L -> extrude() {A};\n" + kA), "bad.rule:2:6", "extrude takes 1 argument, this call gives 0"},
        {"TooManyArguments", lotThen("L -> scale(1, 1, 1, 1) {A};\n" + kA), "bad.rule:2:6", "scale takes 3 arguments, this call gives 4"},
        {"MoreThanTheOptionalArguments", lotThen("L -> insert(\"w.obj\", 1, 1, 1, 1);\n"), "bad.rule:2:6",
         "insert takes 1 to 4 arguments, this call gives 5"},
        {"VariadicWithoutArguments", lotThen("L -> subdiv() {A};\n" + kA), "bad.rule:2:6",
         "subdiv takes at least 1 argument, this call gives 0"},
        {"RepeatSubdivWithoutPercentages", lotThen("L -> repeat_subdiv(3) {A};\n" + kA), "bad.rule:2:6",
         "repeat_subdiv takes at least 2 arguments, this call gives 1"},
        {"LotSplitNonUniformWrongCount", lotThen("L -> lot_split(2, 1, 50, 50) {A};\n" + kA), "bad.rule:2:6",
         "lot_split takes 2 arguments (splits in x and y) or 2 + Divisions_x + Divisions_y (5 here), this call gives 4"},
        {"StringForNumber", lotThen("L -> extrude(\"3\") {A};\n" + kA), "bad.rule:2:14",
         "extrude expects a number here, found the string \"3\""},
        {"NumberForString", lotThen("L -> add_material(3, 1, 0, 0) {A};\n" + kA), "bad.rule:2:19",
         "add_material expects a \"string\" here (a name or a file in quotes), found number 3"},
        {"NameForString", lotThen("L -> add_material(blue, 0, 0, 1) {A};\n" + kA), "bad.rule:2:19",
         "add_material expects a \"string\" here (a name or a file in quotes), found 'blue' (not in quotes)"},
        {"NonWholeNumberForInteger", lotThen("L -> uniform_subdiv(2.5) {A};\n" + kA), "bad.rule:2:21",
         "uniform_subdiv expects a whole number here, found 2.5"},
        {"BoolNotZeroOrOne", lotThen("L -> corners(0.5, 0.5, 2, 1, 1, 1) {A};\n" + kA), "bad.rule:2:24",
         "corners expects 0 or 1 here, found 2"},
        {"RandLowerBoundAboveUpper", lotThen("L -> extrude(rand(5, -2)) {A};\n" + kA), "bad.rule:2:14",
         "rand(a, b) needs a <= b, found rand(5, -2)"},
        {"RandWithoutWholeNumber", lotThen("L -> uniform_subdiv(rand(1.2, 1.8)) {A};\n" + kA), "bad.rule:2:21",
         "rand(1.2, 1.8) holds no whole number, but uniform_subdiv needs one here"},
        {"RandAsLotSplitCountWithSeveralSuccessors", lotThen("L -> lot_split(rand(1, 3), 2) {A | A};\n" + kA), "bad.rule:2:16",
         "lot_split's number of splits is rand() here, which needs a single successor (with several, their round robin needs "
         "constant counts)"},
        {"LotSplitCountTooLarge", lotThen("L -> lot_split(1, 5000) {A};\n" + kA), "bad.rule:2:19",
         "lot_split's number of splits in y must be a whole constant from 0 to 255, found 5000"},
        {"RandAsCompFaceCount", lotThen("L -> comp(rand(3, 6)) {A};\n" + kA), "bad.rule:2:11",
         "comp's number of side faces must be a whole constant from 3 to 64 (rand() is not allowed here)"},
        {"CompWithTwoFaces", lotThen("L -> comp(2) {A};\n" + kA), "bad.rule:2:11",
         "comp's number of side faces must be a whole constant from 3 to 64, found 2"},
        {"RandAsInsertFlag", lotThen("L -> insert(\"w.obj\", rand(0, 1));\n"), "bad.rule:2:22",
         "insert's flags are constants 0 or 1 (rand() is not allowed here)"},
        {"LotSplitSimpleFractionAboveOne", lotThen("L -> lot_split_simple(1.5, 0.5) {A};\n" + kA), "bad.rule:2:23",
         "lot_split_simple's fractions lie in [0, 1]"},
        {"MaterialHandleWithASpace", lotThen("L -> add_material(\"a b\", 1, 0, 0) {A};\n" + kA), "bad.rule:2:19",
         "a material handle is letters, digits, '_', '-' and '.', found \"a b\""},
        {"HandleAsArgument", lotThen("L -> extrude(Height) {A};\n" + kA), "bad.rule:2:14",
         "expected an argument (a number, an attr, rand(a, b) or a \"string\"), found handle 'Height'"},
        // --- stochastic rules -------------------------------------------------------------
        {"ProbabilitiesDoNotAddUpToOne", lotThen("L -> [0.5] extrude(1) {A}, [0.3] extrude(2) {A};\n" + kA), "bad.rule:2:7",
         "the probabilities of this stochastic rule add up to 0.8, not 1 (castlemaker-crl.txt §3.7.4)"},
        {"ProbabilityAboveOne", lotThen("L -> [1.5] extrude(1) {A}, [-0.5] extrude(2) {A};\n" + kA), "bad.rule:2:7",
         "a probability lies in [0, 1], found 1.5"},
        {"NegativeProbability", lotThen("L -> [-0.5] extrude(1) {A}, [1.5] extrude(2) {A};\n" + kA), "bad.rule:2:7",
         "a probability lies in [0, 1], found -0.5"},
        {"AlternativeWithoutProbability", lotThen("L -> [0.5] extrude(1) {A}, extrude(2) {A};\n" + kA), "bad.rule:2:28",
         "every alternative of a stochastic rule has a probability: [p] extrude(...)"},
        {"FirstAlternativeWithoutProbability", lotThen("L -> extrude(1) {A}, [0.5] extrude(2) {A};\n" + kA), "bad.rule:2:6",
         "every alternative of a stochastic rule has a probability: [p] extrude(...)"},
        {"LotWithProbability", "L = [1] rect(0, 0, 1, 1);\n", "bad.rule:1:6", "a direct lot (Handle = rect(...)) has no probability"},
        // --- successors -------------------------------------------------------------------
        {"SuccessorNeverDefined", lotThen("L -> extrude(3) {Tower};\n"), "bad.rule:2:18",
         "handle 'Tower' is never defined (no rule Tower -> ...; and no lot Tower = ...;)"},
        {"SuccessorOnATerminal", lotThen("L -> insert_cylinder(1, 1, 1, 20) {X};\nX -> insert_volume(1, 1, 1, 0, 0, 1);\n"),
         "bad.rule:2:36", "insert_cylinder is a terminal and takes no successor"},
        {"MissingSuccessor", lotThen("L -> extrude(3);\n"), "bad.rule:2:6", "extrude needs a successor {Handle}"},
        {"EmptySuccessorList", lotThen("L -> extrude(1) {};\n"), "bad.rule:2:18",
         "expected a successor handle (a name starting with a capital letter), found '}'"},
        {"UnclosedSuccessorList", lotThen("L -> extrude(1) {A;\n" + kA), "bad.rule:2:19",
         "expected '|' between successors or '}' to close those opened at line 2, found ';'"},
        {"SubdivPercentagesNotHundred", lotThen("L -> subdiv(50, 30) {A | A};\n" + kA), "bad.rule:2:13",
         "the percentages of subdiv add up to 80, not 100"},
        {"SubdivMoreSharesThanSuccessors", lotThen("L -> subdiv(50, 50) {A};\n" + kA), "bad.rule:2:6",
         "subdiv has 2 percentages and 1 successor; they must be as many"},
        {"RepeatSplitFewerSharesThanSuccessors", lotThen("L -> repeat_split(2, 100) {A | A};\n" + kA), "bad.rule:2:6",
         "repeat_split has 1 percentage and 2 successors; they must be as many"},
        // --- direct and indirect rules ----------------------------------------------------
        {"RectInAnIndirectRule", lotThen("L -> rect(0, 0, 1, 1);\n"), "bad.rule:2:6", "rect makes a direct lot: write Handle = rect(...);"},
        {"ExtrudeInADirectRule", "L = extrude(3);\n", "bad.rule:1:5",
         "a direct rule (Handle = ...) makes a lot with rect(x1, y1, x2, y2) or circ(cx, cy, r), not extrude"},
        {"LotWithASuccessor", "L = rect(0, 0, 10, 10) {A};\n" + kA, "bad.rule:1:25",
         "rect makes a lot, which takes no successor: its rules follow as Handle -> function(...) {...};"},
        {"NoDirectLot", "L -> extrude(1) {A};\n" + kA, "bad.rule:1:1",
         "no lot: a rule file needs a direct lot (Handle = rect(x1, y1, x2, y2); or circ(cx, cy, r);)"},
        {"EmptyFile", "", "bad.rule:1:1", "no lot: a rule file needs a direct lot (Handle = rect(x1, y1, x2, y2); or circ(cx, cy, r);)"},
        {"RecursionNeverEnds", lotThen("L -> extrude(1) {A};\nA -> extrude(2) {A};\n"), "bad.rule:3:18",
         "recursion never ends: A -> A and no rule on the way is stochastic (a recursive rule must be, castlemaker-crl.txt ch. 4-5)"},
        {"RecursionThroughTwoHandlesNeverEnds", lotThen("L -> extrude(1) {A};\nA -> extrude(2) {B};\nB -> scale(1, 1, 1) {A};\n"),
         "bad.rule:4:22",
         "recursion never ends: A -> B -> A and no rule on the way is stochastic (a recursive rule must be, castlemaker-crl.txt ch. 4-5)"},
        // --- form: handles, arrows, ';' ---------------------------------------------------
        {"MissingSemicolon", lotThen("L -> extrude(3) {A}\n" + kA), "bad.rule:2:20", "expected ';' to end the rule, found 'A' at line 3"},
        {"MissingSemicolonBeforeTheNextRule", "L = rect(0, 0, 10, 10)\nL -> extrude(3) {A};\n" + kA, "bad.rule:1:23",
         "expected ';' to end the rule, found 'L' at line 2, which starts the next rule"},
        {"MissingSemicolonAfterAttr", "attr h = 3\n" + kLot, "bad.rule:1:11", "expected ';' after the attr definition, found 'L' at line 2"},
        {"MissingArrow", lotThen("L extrude(1) {A};\n"), "bad.rule:2:3", "expected '->' (or '→') or '=' after the handle L, found 'extrude'"},
        {"LowercaseSuccessor", lotThen("L -> extrude(3) {tower};\n"), "bad.rule:2:18",
         "expected a successor handle (a name starting with a capital letter), found 'tower'"},
        {"LowercasePredecessor", lotThen("L -> extrude(3) {A};\ntower -> insert_volume(1, 1, 1, 0, 0, 1);\n"), "bad.rule:3:1",
         "a rule starts with a handle, a name with a capital first letter (castlemaker-crl.txt §3.6.2), found 'tower'"},
        {"HandleWithDoubleUnderscore", lotThen("L -> extrude(1) {A__b};\nA__b -> insert_volume(1, 1, 1, 0, 0, 1);\n"), "bad.rule:3:1",
         "handles with '__' are kept for shapevo's own names"},
        // --- attrs ------------------------------------------------------------------------
        {"AttrNameNotLowercase", "attr Height = 3;\n" + kLot, "bad.rule:1:6",
         "attr names are lowercase letters, digits and '_' (castlemaker-crl.txt §3.6.5), found 'Height'"},
        {"AttrDefinedTwice", "attr h = 3;\nattr h = 4;\n" + kLot, "bad.rule:2:6", "attr 'h' is defined twice"},
        {"UnknownAttr", lotThen("L -> extrude(height) {A};\n" + kA), "bad.rule:2:14",
         "unknown attr 'height' (attrs are defined with attr name = value;)"},
        {"AttrValueNotANumber", "attr h = wide;\n" + kLot, "bad.rule:1:10", "expected the attr's value (a number), found 'wide'"},
        {"AttrWithAReservedName", "attr scope = 1;\n" + kLot, "bad.rule:1:6", "'scope' is a reserved name in shapevo and cannot name an attr"},
        // --- lexical ----------------------------------------------------------------------
        {"UnclosedComment", kLot + "/* the towers\nL -> extrude(3) {A};\n", "bad.rule:2:1", "comment '/*' is never closed"},
        {"UnclosedString", lotThen("L -> add_material(\"blue, 0, 0, 1) {A};\n"), "bad.rule:2:19", "string is not closed on its line"},
        {"StrayCharacter", lotThen("L -> extrude(3) @ {A};\n"), "bad.rule:2:17", "unexpected character '@'"},
        {"StrayControlByte", lotThen("L -> extrude(3)\x01 {A};\n"), "bad.rule:2:16", "unexpected byte 0x01"},
        {"MalformedNumber", lotThen("L -> extrude(1.2.3) {A};\n"), "bad.rule:2:14", "malformed number '1.2.3'"},
        {"NumberTooLarge", lotThen("L -> extrude(1e39) {A};\n"), "bad.rule:2:14", "number 1e39 is too large"},
    };
    return all;
}

class RuleMalformed : public ::testing::TestWithParam<MalformedRule> {};

TEST_P(RuleMalformed, IsRejectedWithItsPlaceAndMessage) {
    const MalformedRule& m = GetParam();
    try {
        parseGrammar(m.text, "bad.rule");
        FAIL() << "expected InputError for:\n" << m.text;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), m.where + ": " + m.message);
        EXPECT_EQ(e.file(), "bad.rule");
    }
}

INSTANTIATE_TEST_SUITE_P(RuleCases, RuleMalformed, ::testing::ValuesIn(ruleCases()),
                         [](const ::testing::TestParamInfo<MalformedRule>& info) { return std::string(info.param.name); });

// --- cases with other files: includes, OBJs, textures, inserted rule files -----------------

struct MalformedFiles {
    const char* name;
    std::vector<std::pair<std::string, std::string>> files;  ///< name (in the temp folder) and text; the first is read
    std::string where;    ///< expected "FILE:LINE:COL", FILE relative to the temp folder
    std::string message;  ///< the expected message, "{dir}" standing for the temp folder
};

std::ostream& operator<<(std::ostream& os, const MalformedFiles& m) { return os << m.name; }

const std::string kValid = kLot + "L -> extrude(1) {A};\n" + kA;

const std::vector<MalformedFiles>& fileCases() {
    static const std::vector<MalformedFiles> all = {
        {"MissingInclude", {{"main.rule", "include \"parts.rule\";\n" + kValid}}, "main.rule:1:9",
         "cannot open included rule file 'parts.rule' (looked for {dir}/parts.rule)"},
        {"IncludeOfAFolder", {{"main.rule", "include \"sub\";\n" + kValid}, {"sub/x.rule", kValid}}, "main.rule:1:9",
         "cannot open included rule file 'sub' (looked for {dir}/sub)"},
        {"IncludeCycle", {{"a.rule", "include \"b.rule\";\n" + kValid}, {"b.rule", "// b\n#include \"a.rule\"\n"}}, "b.rule:2:10",
         "include cycle: a.rule -> b.rule -> a.rule"},
        {"IncludesItself", {{"a.rule", "include \"a.rule\";\n" + kValid}}, "a.rule:1:9", "include cycle: a.rule -> a.rule"},
        {"ErrorInAnIncludedFile", {{"main.rule", "include \"parts.rule\";\n" + kValid}, {"parts.rule", "B -> extrude(1) {C};\n"}},
         "parts.rule:1:18", "handle 'C' is never defined (no rule C -> ...; and no lot C = ...;)"},
        {"MissingObj", {{"main.rule", lotThen("L -> insert(\"data/nowhere.obj\");\n")}}, "main.rule:2:13",
         "cannot open OBJ 'data/nowhere.obj' (looked for {dir}/data/nowhere.obj)"},
        {"BrokenObjKeepingItsHeight", {{"main.rule", lotThen("L -> insert(\"bad.obj\", 0, 0, 1);\n")}, {"bad.obj", "v 1 2\nf 1 2 3\n"}},
         "main.rule:2:13", "OBJ 'bad.obj': vertex needs 3 coordinates"},
        {"MissingTexture", {{"main.rule", lotThen("L -> add_texture(\"stone\", \"data/stone.png\", 1, 1) {A};\n" + kA)}}, "main.rule:2:27",
         "cannot open texture 'data/stone.png' (looked for {dir}/data/stone.png)"},
        // The .grammar language has no texture statement yet: an add_texture whose file exists
        // is refused where it stands, by the statement it translates to.
        {"TextureFileThatIsNotAPng",
         {{"main.rule", lotThen("L -> add_texture(\"stone\", \"stone.png\", 2, 1) {A};\n" + kA)}, {"stone.png", "png"}}, "main.rule:2:6",
         "texture 'stone.png' is not a PNG (it does not start with the PNG signature) (in its translation to the shapevo language: "
         "texture \"stone\" \"stone.png\" (2, 1))"},
        {"MissingInsertedRuleFile", {{"main.rule", lotThen("L -> insert(\"door.rule\");\n")}}, "main.rule:2:13",
         "cannot open rule file 'door.rule' (looked for {dir}/door.rule)"},
        {"InsertedRuleFileWithoutLot", {{"main.rule", lotThen("L -> insert(\"door.rule\");\n")}, {"door.rule", "attr w = 1;\n"}},
         "main.rule:2:13", "the inserted rule file has no lot"},
        {"InsertCycle",
         {{"main.rule", lotThen("L -> insert(\"sub/inner.rule\");\n")}, {"sub/inner.rule", lotThen("L -> insert(\"../main.rule\");\n")}},
         "sub/inner.rule:2:13", "insert cycle: main.rule -> sub/inner.rule -> main.rule (rule files that insert each other never end)"},
        {"InsertsItself", {{"main.rule", lotThen("L -> insert(\"main.rule\");\n")}}, "main.rule:2:13",
         "insert cycle: main.rule -> main.rule (rule files that insert each other never end)"},
    };
    return all;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
    return s;
}

class RuleFilesMalformed : public ::testing::TestWithParam<MalformedFiles> {};

TEST_P(RuleFilesMalformed, IsRejectedWithItsPlaceAndMessage) {
    const MalformedFiles& m = GetParam();
    TempDir dir;
    for (const auto& [name, text] : m.files) {
        std::filesystem::create_directories(std::filesystem::path(dir.file(name)).parent_path());
        writeFile(dir.file(name), text);
    }
    try {
        loadGrammar(dir.file(m.files.front().first));
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir.path().string() + "/" + m.where + ": " + replaced(m.message, "{dir}", dir.path().string()));
    }
}

INSTANTIATE_TEST_SUITE_P(RuleFileCases, RuleFilesMalformed, ::testing::ValuesIn(fileCases()),
                         [](const ::testing::TestParamInfo<MalformedFiles>& info) { return std::string(info.param.name); });

TEST(RuleMalformedCases, AtLeastThirtyDistinctCases) {
    EXPECT_GE(ruleCases().size() + fileCases().size(), 30u);
    std::vector<std::string> names;
    for (const MalformedRule& m : ruleCases()) names.push_back(m.name);
    for (const MalformedFiles& m : fileCases()) names.push_back(m.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "case names must be unique";
}

// The translator's graph walks keep their own stacks: a chain of 70,000 handles is a clear
// error (the translation's rule limit), never a stack overflow (100,000 was one), and a chain of
// 3,000 compiles; a cycle
// through 20,000 handles with no stochastic rule, whose message shortens the cycle.
TEST(RuleMalformedDeep, ChainOfSeventyThousandHandlesIsAnErrorNotACrash) {
    try {
        parseGrammar(chain(70000), "bad.rule");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "bad.rule:60496:1: too many rules (at most 65535) (in its translation to the shapevo "
                                         "language: rule H60493 {)");  // with the chain's gene wrappers
    }
    // 30,000 handles in a chain are deeper than inline calls may nest: the chain is cut into
    // genes (a child slot every few levels) and compiles.
    const Grammar g = parseGrammar(chain(3000), "deep.rule");
    EXPECT_GT(g.mandatoryGenes[g.start], 200u);
}

TEST(RuleMalformedDeep, CycleThroughTwentyThousandHandlesIsReportedShortly) {
    std::string text = lotThen("L -> extrude(1) {H0};\n");
    const int n = 20000;
    for (int i = 0; i < n; ++i) text += "H" + std::to_string(i) + " -> extrude(1) {H" + std::to_string((i + 1) % n) + "};\n";
    try {
        parseGrammar(text, "bad.rule");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "bad.rule:20002:23: recursion never ends: H0 -> H1 -> H2 -> H3 -> H4 -> ... (19990 more) -> "
                                         "H19995 -> H19996 -> H19997 -> H19998 -> H19999 -> H0 and no rule on the way is stochastic "
                                         "(a recursive rule must be, castlemaker-crl.txt ch. 4-5)");
    }
}

// A stochastic recursion is no error (§5.2): it becomes an optional child slot, a gene per step.
TEST(RuleMalformedDeep, StochasticRecursionIsAccepted) {
    const Grammar g = parseGrammar(lotThen("L -> extrude(1) {A};\nA -> [0.8] insert_volume(1, 1, 1, 0, 0, 1) {A}, "
                                           "[0.2] insert_volume(1, 1, 1, 1, 1, 1);\n"),
                                   "ok.rule");
    bool optional = false;
    for (const Rule& r : g.rules)
        for (const Slot& s : r.slots) optional = optional || s.optional;
    EXPECT_TRUE(optional);
}

}  // namespace
}  // namespace shapevo
