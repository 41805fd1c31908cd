// Tests of graph/yaml_tree: scalars resolved as PyYAML 6's SafeLoader resolves them (a table
// checked against PyYAML), nesting and marks, every refusal with its message and place (syntax,
// tabs, duplicate keys, unsafe tags, alias bombs, deep nesting, several documents, size, bad
// UTF-8, NUL bytes), and the original tool's four example files read from ../shared/.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "graph/yaml_tree.hpp"
#include "../test_support.hpp"

namespace yaml_tree_test {

using shapevo::InputError;
using shapevo::graph::parseYaml;
using shapevo::graph::readYamlFile;
using shapevo::graph::YamlLimits;
using shapevo::graph::YamlNode;
using Kind = YamlNode::Kind;

enum Expected { Null, Bool, Int, Float, String, Error };

struct ScalarCase {
    const char* text;
    Expected kind;
    const char* value;  // Int/Float: the number; Bool: true/false; String: the text; Error: part of the message
};

// Each plain scalar written as "v: <text>". Generated once with PyYAML 6.0 (CLoader and the pure
// loader share resolver.py):
//   python3 -c 'import yaml; print(repr(yaml.safe_load("v: " + s)["v"]))'
// The comments mark where shapevo differs, each a refusal or a string where PyYAML gives a value
// the original tool could not use.
const ScalarCase kScalars[] = {
    {"yes", Bool, "true"},
    {"Yes", Bool, "true"},
    {"YES", Bool, "true"},
    {"no", Bool, "false"},
    {"No", Bool, "false"},
    {"NO", Bool, "false"},
    {"true", Bool, "true"},
    {"True", Bool, "true"},
    {"TRUE", Bool, "true"},
    {"false", Bool, "false"},
    {"False", Bool, "false"},
    {"FALSE", Bool, "false"},
    {"on", Bool, "true"},
    {"On", Bool, "true"},
    {"ON", Bool, "true"},
    {"off", Bool, "false"},
    {"Off", Bool, "false"},
    {"OFF", Bool, "false"},
    {"y", String, "y"},
    {"n", String, "n"},
    {"Y", String, "Y"},
    {"N", String, "N"},
    {"yEs", String, "yEs"},
    {"oN", String, "oN"},
    {"tRUE", String, "tRUE"},
    {"~", Null, ""},
    {"null", Null, ""},
    {"Null", Null, ""},
    {"NULL", Null, ""},
    {"nULL", String, "nULL"},
    {"None", String, "None"},
    {"none", String, "none"},
    {"", Null, ""},
    {"0", Int, "0"},
    {"00", Int, "0"},
    {"-0", Int, "0"},
    {"+0", Int, "0"},
    {"12", Int, "12"},
    {"-12", Int, "-12"},
    {"+12", Int, "12"},
    {"1_000", Int, "1000"},
    {"1__", Int, "1"},
    {"_1", String, "_1"},
    {"0777", Int, "511"},
    {"0778", String, "0778"},
    {"08", String, "08"},
    {"0_8", String, "0_8"},
    {"0b101", Int, "5"},
    {"0b1_0", Int, "2"},
    {"-0b11", Int, "-3"},
    {"0b2", String, "0b2"},
    {"0x1F", Int, "31"},
    {"0xff_ff", Int, "65535"},
    {"-0x1f", Int, "-31"},
    {"0x", String, "0x"},
    {"0xG", String, "0xG"},
    {"0o17", String, "0o17"},
    {"190:20:30", Int, "685230"},
    {"1:59", Int, "119"},
    {"1:60", String, "1:60"},
    {"0:1", String, "0:1"},
    {"-1:30", Int, "-90"},
    {"1:1:1", Int, "3661"},
    {"9223372036854775807", Int, "9223372036854775807"},
    {"-9223372036854775808", Int, "-9223372036854775808"},
    {"9223372036854775808", Error, "does not fit in 64 bits"},  // PyYAML: a Python int
    {"1.5", Float, "1.5"},
    {"-1.5", Float, "-1.5"},
    {"+1.5", Float, "1.5"},
    {"1.", Float, "1.0"},
    {"0.", Float, "0.0"},
    {".5", Float, "0.5"},
    {"-.5", String, "-.5"},
    {"+.5", String, "+.5"},
    {"1e3", String, "1e3"},
    {"1E3", String, "1E3"},
    {"1.0e3", String, "1.0e3"},
    {"1.0e+3", Float, "1000.0"},
    {"1.0E-3", Float, "0.001"},
    {"1.e+3", Float, "1000.0"},
    {"1_000.5", Float, "1000.5"},
    {"1.__", Float, "1.0"},
    {"._", String, "._"},
    {"._5", String, "._5"},
    {"08.5", Float, "8.5"},
    {"190:20:30.15", Float, "685230.15"},
    {"1:30.5", Float, "90.5"},
    {"1:60.5", String, "1:60.5"},
    {".inf", Float, "inf"},
    {".Inf", Float, "inf"},
    {".INF", Float, "inf"},
    {"-.inf", Float, "-inf"},
    {"+.inf", Float, "inf"},
    {".iNf", String, ".iNf"},
    {".nan", Float, "nan"},
    {".NaN", Float, "nan"},
    {".NAN", Float, "nan"},
    {"-.nan", String, "-.nan"},
    {"nan", String, "nan"},
    {"inf", String, "inf"},
    {"1.0e+999", Float, "inf"},
    {"1.0e-999", Float, "0.0"},
    {"3.14159", Float, "3.14159"},
    {"2001-12-14", String, "2001-12-14"},  // PyYAML: a date; shapevo: a string
    {"12abc", String, "12abc"},
    {"0x1F.5", String, "0x1F.5"},
    {"0b_", Error, "is not an integer"},  // PyYAML: ValueError
    {"0x_", Error, "is not an integer"},  // PyYAML: ValueError
    {"=", Error, "value key"},  // PyYAML: no constructor for !!value
    {"<<", Error, "merge keys"},  // PyYAML: no constructor for !!merge
};

// Parses `text`, expecting an InputError whose message holds `part` at "line:column".
void expectError(const std::string& text, const std::string& where, const std::string& part,
                 const YamlLimits& limits = {}) {
    try {
        parseYaml(text, "g.yml", limits);
        ADD_FAILURE() << "no error for: " << text.substr(0, 60);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "g.yml");
        EXPECT_EQ(e.where(), where) << e.what();
        EXPECT_NE(e.message().find(part), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

const YamlNode& at(const YamlNode& map, const char* key) {
    const YamlNode* v = map.find(key);
    if (!v) throw std::runtime_error(std::string("no key ") + key);
    return *v;
}

std::string originalExample(const std::string& name) {
    return std::string(SHAPEVO_SOURCE_DIR) + "/../shared/graph-grammar/original-examples/" + name;
}

}  // namespace yaml_tree_test

using namespace yaml_tree_test;

TEST(YamlTreeResolve, PlainScalarsResolveAsPyYamlSafeLoader) {
    for (const ScalarCase& c : kScalars) {
        SCOPED_TRACE(std::string("v: ") + c.text);
        const std::string text = std::string("v: ") + c.text + "\n";
        if (c.kind == Error) {
            expectError(text, "1:4", c.value);
            continue;
        }
        const YamlNode doc = parseYaml(text, "t.yml");
        const YamlNode& v = at(doc, "v");
        EXPECT_EQ(v.text, c.text);
        EXPECT_FALSE(v.quoted);
        switch (c.kind) {
        case Null: EXPECT_EQ(v.kind, Kind::Null); break;
        case Bool:
            EXPECT_EQ(v.kind, Kind::Bool);
            EXPECT_EQ(v.boolean, std::string(c.value) == "true");
            break;
        case Int:
            EXPECT_EQ(v.kind, Kind::Int);
            EXPECT_EQ(v.integer, std::stoll(c.value));
            break;
        case Float:
            EXPECT_EQ(v.kind, Kind::Float);
            if (std::string(c.value) == "nan")
                EXPECT_TRUE(std::isnan(v.number));
            else
                EXPECT_EQ(v.number, std::strtod(c.value, nullptr));
            break;
        case String: EXPECT_EQ(v.kind, Kind::String); break;
        case Error: break;
        }
    }
    EXPECT_GE(std::size(kScalars), 60u);
}

TEST(YamlTreeResolve, QuotedAndBlockScalarsAreStrings) {
    const YamlNode doc = parseYaml("a: '12'\nb: \"true\"\nc: |\n  x\n  y\nd: >\n  folded\n  text\ne: ''\n", "t.yml");
    for (const char* key : {"a", "b", "c", "d", "e"}) {
        EXPECT_EQ(at(doc, key).kind, Kind::String) << key;
        EXPECT_TRUE(at(doc, key).quoted) << key;
    }
    EXPECT_EQ(at(doc, "a").text, "12");
    EXPECT_EQ(at(doc, "c").text, "x\ny\n");
    EXPECT_EQ(at(doc, "d").text, "folded text\n");
    EXPECT_EQ(at(doc, "e").text, "");
}

TEST(YamlTreeResolve, MultiLinePlainAndSingleQuotedScalarsAreFolded) {
    const YamlNode doc = parseYaml("a: one\n  two\n   three\nb: 'x\n  y'\n", "t.yml");
    EXPECT_EQ(at(doc, "a").text, "one two three");
    EXPECT_EQ(at(doc, "a").kind, Kind::String);
    EXPECT_EQ(at(doc, "b").text, "x y");
}

TEST(YamlTreeResolve, ExplicitCoreTagsAreHonoured) {
    const YamlNode doc = parseYaml(
        "s: !!str 12\ni: !!int '0x10'\nf: !!float 1\nb: !!bool 'Yes'\nn: !!null whatever\nx: ! 12\n"
        "l: !!seq [1]\nm: !!map {k: 1}\nq: !<tag:yaml.org,2002:int> 7\n",
        "t.yml");
    EXPECT_EQ(at(doc, "s").kind, Kind::String);
    EXPECT_EQ(at(doc, "i").kind, Kind::Int);
    EXPECT_EQ(at(doc, "i").integer, 16);
    EXPECT_EQ(at(doc, "f").kind, Kind::Float);
    EXPECT_EQ(at(doc, "f").number, 1.0);
    EXPECT_EQ(at(doc, "b").kind, Kind::Bool);
    EXPECT_TRUE(at(doc, "b").boolean);
    EXPECT_EQ(at(doc, "n").kind, Kind::Null);
    EXPECT_EQ(at(doc, "x").kind, Kind::Int);  // '!' asks for the implicit resolution, as in PyYAML
    EXPECT_EQ(at(doc, "l").kind, Kind::Sequence);
    EXPECT_EQ(at(doc, "m").kind, Kind::Mapping);
    EXPECT_EQ(at(doc, "q").integer, 7);
    expectError("a: !!int 1.5\n", "1:4", "'1.5' is not an integer");
    expectError("a: !!bool maybe\n", "1:4", "is not a boolean");
    expectError("a: !!float x\n", "1:4", "is not a number");
    expectError("a: !!str [1]\n", "1:4", "does not fit a sequence");
    expectError("a: !!seq x\n", "1:4", "is given to a scalar");
}

TEST(YamlTree, NestingAndMarks) {
    const std::string text =
        "# a comment\n"
        "graphs:\n"
        "  g:\n"
        "    vertices:\n"
        "    - {id: 1, attr: {x: '0'}}\n"
        "    - id: 2\n"
        "      attr: {label: \"é b\", y: 2.5}\n"
        "list: [a, [b, c], {d: e}]\n";
    const YamlNode doc = parseYaml(text, "t.yml");
    ASSERT_EQ(doc.kind, Kind::Mapping);
    EXPECT_EQ(doc.where(), "2:1");
    ASSERT_EQ(doc.entries.size(), 2u);
    EXPECT_EQ(doc.entries[0].first.text, "graphs");
    EXPECT_EQ(doc.entries[0].first.where(), "2:1");
    const YamlNode& vertices = at(at(at(doc, "graphs"), "g"), "vertices");
    ASSERT_EQ(vertices.kind, Kind::Sequence);
    ASSERT_EQ(vertices.items.size(), 2u);
    EXPECT_EQ(vertices.where(), "5:5");
    EXPECT_EQ(vertices.items[0].where(), "5:7");
    EXPECT_EQ(at(vertices.items[0], "id").where(), "5:12");
    EXPECT_EQ(at(vertices.items[1], "id").integer, 2);
    EXPECT_EQ(at(vertices.items[1], "id").where(), "6:11");
    const YamlNode& attr = at(vertices.items[1], "attr");
    EXPECT_EQ(at(attr, "label").text, "é b");
    EXPECT_EQ(at(attr, "y").where(), "7:31");  // columns count characters: 'é' is one
    EXPECT_EQ(at(attr, "y").number, 2.5);
    const YamlNode& list = at(doc, "list");
    ASSERT_EQ(list.items.size(), 3u);
    EXPECT_EQ(list.items[1].items[1].text, "c");
    EXPECT_EQ(list.items[1].items[1].where(), "8:15");
    EXPECT_EQ(at(list.items[2], "d").text, "e");
    EXPECT_EQ(doc.find("nothing"), nullptr);
    EXPECT_EQ(list.find("a"), nullptr);  // not a mapping
}

TEST(YamlTree, EmptyFileIsNullAndBomIsSkipped) {
    EXPECT_EQ(parseYaml("", "t.yml").kind, Kind::Null);
    EXPECT_EQ(parseYaml("# only a comment\n\n", "t.yml").kind, Kind::Null);
    EXPECT_EQ(parseYaml("---\n", "t.yml").kind, Kind::Null);
    const YamlNode doc = parseYaml("\xEF\xBB\xBF" "a: 1\n", "t.yml");
    EXPECT_EQ(at(doc, "a").integer, 1);
}

TEST(YamlTree, AliasesAreExpandedCopies) {
    const YamlNode doc = parseYaml("a: &x {k: [1, 2]}\nb: *x\nc: &s hello\nd: *s\n", "t.yml");
    EXPECT_EQ(at(at(doc, "b"), "k").items.size(), 2u);
    EXPECT_EQ(at(at(doc, "b"), "k").items[1].integer, 2);
    EXPECT_EQ(at(doc, "b").where(), "2:4");  // the copy is placed where the alias is
    EXPECT_EQ(at(doc, "d").text, "hello");
}

TEST(YamlTree, DescribeNamesKindAndValue) {
    const YamlNode doc = parseYaml("[~, true, 5, 1.5, abc, [], {}]", "t.yml");
    const char* expected[] = {"null", "the boolean true", "the integer 5", "the number 1.5", "the string 'abc'",
                              "a sequence", "a mapping"};
    ASSERT_EQ(doc.items.size(), 7u);
    for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(doc.items[i].describe(), expected[i]);
}

TEST(YamlTreeErrors, SyntaxErrorsCarryLibyamlsProblemAndPlace) {
    expectError("a: b: c\n", "1:5", "YAML syntax: mapping values are not allowed in this context");
    expectError("a: [1, 2\nb: 3\n", "2:2", "YAML syntax: did not find expected ',' or ']' (while parsing a flow sequence at 1:4)");
    expectError("a: 'open\n", "2:1", "YAML syntax: found unexpected end of stream");
    expectError("a: [1, 2", "1:9", "YAML syntax");  // the end of a file without a final newline
}

TEST(YamlTreeErrors, TabIndentationIsASyntaxError) {
    expectError("a:\n\tb: 1\n", "2:1", "YAML syntax: found character that cannot start any token");
}

TEST(YamlTreeErrors, DuplicateKeyNamesBothPlaces) {
    expectError("a: 1\nb: 2\na: 3\n", "3:1", "the key 'a' is repeated in this mapping (first at 1:1)");
    expectError("{1: x, 1.0: y}\n", "1:8", "first at 1:2");  // keys compare as Python's dict does
    expectError("{~: x, null: y}\n", "1:8", "first at 1:2");
    EXPECT_NO_THROW(parseYaml("{1: x, '1': y, a: {a: 1}}\n", "t.yml"));  // an int and a string differ
}

TEST(YamlTreeErrors, ComplexKeyAndMergeKeyAreRefused) {
    expectError("? [a]\n: 1\n", "1:3", "a mapping key must be a scalar");
    expectError("base: &b {x: 1}\nc:\n  <<: *b\n", "3:3", "merge keys ('<<') are not supported");
}

TEST(YamlTreeErrors, UnsafeTagsAreRefused) {
    expectError("a: !!python/object/apply:os.system ['ls']\n", "1:4",
                "the tag !!python/object/apply:os.system is refused");
    expectError("a: !!python/name:os.system x\n", "1:4", "the tag !!python/name:os.system is refused");
    expectError("a: !custom 1\n", "1:4", "the tag !custom is refused");
    expectError("a: !!binary aGk=\n", "1:4", "the tag !!binary is refused");
    expectError("a: !!set {x}\n", "1:4", "the tag !!set is refused");
}

TEST(YamlTreeErrors, AliasBombFailsFast) {
    std::string bomb = "a: &a [x, x, x, x, x, x, x, x, x]\n";
    for (char c = 'b'; c <= 'i'; ++c) {
        bomb += std::string(1, c) + ": &" + c + " [";
        for (int i = 0; i < 9; ++i) bomb += std::string(i ? ", *" : "*") + char(c - 1);
        bomb += "]\n";
    }
    try {
        parseYaml(bomb, "g.yml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("aliases expand to more than 100000 YAML nodes"), std::string::npos) << e.what();
    }
    YamlLimits limits;
    limits.maxAliasNodes = 1u << 30;  // the total still bounds it
    limits.maxNodes = 50000;
    expectError(bomb, "5:24", "more than 50000 YAML nodes", limits);
}

TEST(YamlTreeErrors, AliasProblemsAreLocated) {
    expectError("a: *nowhere\n", "1:4", "the alias *nowhere names no anchor before it");
    expectError("a: &r [1, *r]\n", "1:11", "inside its own anchor's node");
    expectError("a: &x 1\nb: &x 2\n", "2:4", "the anchor &x is defined twice");
    YamlLimits limits;
    limits.maxDepth = 4;
    expectError("a: &x [[[1]]]\nb: [*x]\n", "2:5", "nests collections deeper than 4 levels", limits);
}

TEST(YamlTreeErrors, DeepNestingFailsCleanly) {
    const std::string deep(100000, '[');
    expectError(deep, "1:65", "collections nested deeper than 64 levels");
    std::string blocks;  // block mappings too
    for (int i = 0; i < 70; ++i) blocks += std::string(2 * i, ' ') + "k:\n";
    expectError(blocks, "65:129", "nested deeper than 64 levels");
}

TEST(YamlTreeErrors, OneDocumentOnly) {
    expectError("a: 1\n---\nb: 2\n", "2:1", "one YAML document expected, found a second one");
    expectError("--- 1\n--- 2\n", "2:1", "one YAML document expected");
}

TEST(YamlTreeErrors, FileOverTheSizeLimitIsRefusedBeforeReading) {
    shapevo::test::TempDir dir;
    const std::string path = dir.file("big.yml");
    {
        std::ofstream out(path);
        for (int i = 0; i < 2000; ++i) out << "key" << i << ": value\n";
    }
    YamlLimits limits;
    limits.maxBytes = 1000;
    try {
        readYamlFile(path, limits);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_NE(e.message().find("more than the limit"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseYaml(std::string(1001, 'a'), "t.yml", limits), InputError);
    limits.maxBytes = 1u << 20;
    EXPECT_EQ(readYamlFile(path, limits).entries.size(), 2000u);
    EXPECT_THROW(readYamlFile(dir.file("missing.yml")), InputError);
}

TEST(YamlTreeErrors, NodeCountIsBounded) {
    YamlLimits limits;
    limits.maxNodes = 100;
    std::string many = "[";
    for (int i = 0; i < 200; ++i) many += "1, ";
    many += "]\n";
    expectError(many, "1:299", "more than 100 YAML nodes", limits);
}

TEST(YamlTreeErrors, InvalidUtf8AndControlCharactersAreRefused) {
    expectError("a: b\nc: \xff\xfe d\n", "2:4", "not UTF-8 text: invalid leading UTF-8 octet");
    expectError("a: \xc3\n", "1:5", "not UTF-8 text: invalid trailing UTF-8 octet (#xA)");
    expectError(std::string("a: b\0c\n", 7), "1:5", "not UTF-8 text: control characters are not allowed (#x0)");
    expectError("a: \x01\n", "1:4", "control characters are not allowed");
    // UTF-16 with its BOM: the original read files as UTF-8 text
    expectError(std::string("\xff\xfe" "a\0:\0 \0" "1\0\n\0", 12), "1:1", "not UTF-8 text");
}

TEST(YamlTreeOriginal, ReadsTheFourExampleFiles) {
    const std::string koch = originalExample("koch_flake.yml");
    if (!std::filesystem::exists(koch)) GTEST_SKIP() << "no " << koch << " (the shared examples folder is absent)";
    const YamlNode flake = readYamlFile(koch);
    const YamlNode& host = at(at(flake, "host_graphs"), "Host 1");
    ASSERT_EQ(at(host, "vertices").items.size(), 3u);
    EXPECT_EQ(at(host, "edges").items.size(), 3u);
    const YamlNode& id = at(at(host, "vertices").items[0], "id");
    EXPECT_EQ(id.kind, Kind::Int);
    EXPECT_GT(id.integer, 1LL << 40);  // CPython object ids
    EXPECT_EQ(at(at(at(host, "edges").items[0], "attr"), ".directed").kind, Kind::Bool);
    EXPECT_EQ(at(at(at(host, "vertices").items[0], "attr"), "x").kind, Kind::String);  // quoted '-4'
    EXPECT_EQ(at(flake, "result_graphs").kind, Kind::Mapping);
    EXPECT_TRUE(at(flake, "result_graphs").entries.empty());

    const YamlNode tree = readYamlFile(originalExample("tree.yml"));
    const YamlNode& tag = at(at(at(at(at(tree, "host_graphs"), "Axiom"), "vertices").items[0], "attr"), ".svg_tag");
    EXPECT_EQ(tag.kind, Kind::String);  // the plain word None
    EXPECT_EQ(tag.text, "None");

    const YamlNode circle = readYamlFile(originalExample("pattern_circle.yml"));
    const YamlNode& attr = at(at(at(at(circle, "host_graphs"), "Axiom"), "vertices").items[0], "attr");
    EXPECT_EQ(at(attr, "finished").kind, Kind::Bool);
    EXPECT_FALSE(at(attr, "finished").boolean);
    EXPECT_EQ(at(attr, "finished").where(), "7:19");
    EXPECT_EQ(at(attr, ".svg_r").text, "3.1cm");

    const YamlNode square = readYamlFile(originalExample("pattern_square.yml"));
    EXPECT_EQ(at(at(square, "global_vars"), "max_num_dots").text, "random.randint(0,2)");
    EXPECT_EQ(at(square, "productions").kind, Kind::Mapping);
}
