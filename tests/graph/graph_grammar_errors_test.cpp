// Malformed graph grammar files (graph-grammar README, sections 1 and 3; issue 41 "Safe"): each
// case is one small change to a valid grammar written here, and must be refused with one
// InputError naming the file, the line and column of the fault, and (where it applies) the
// production and element. Also the errors a derivation raises (an expression failing at derive
// time, .new_pos not a vector, the element limit) and the step limit.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"

namespace graph_grammar_errors_test {

using namespace shapevo;
using namespace shapevo::graph;

// A valid grammar; line numbers matter (the cases below give line:column).
// Grow keeps the vertex labelled 'a' and its edge and adds a vertex and an edge: it applies
// forever, so a derivation stops at max_derivations.all (10).
const char* const kBase = R"yaml(host_graphs:
  Start:
    id: 1
    vertices:
    - id: 2
      attr: {x: 0, y: 0, label: 'a'}
    - id: 3
      attr: {x: 1, y: 0, label: 'b'}
    edges:
    - id: 4
      vertex1: 2
      vertex2: 3
      attr: {.directed: true}
global_vars:
  scale: '2.0'
  count: 'random.randint(1, 3)'
options:
  max_derivations: {all: 10}
productions:
  Grow:
    id: 10
    priority: 0
    vectors: {here: 12, along: [12, 13]}
    mother_graph:
      id: 11
      vertices:
      - id: 12
        attr: {x: 0, y: 0, label: "attr == 'a'"}
      - id: 13
        attr: {x: 1, y: 0}
      edges:
      - id: 14
        vertex1: 12
        vertex2: 13
        attr: {.directed: true}
    mappings:
    - id: 20
      mother_graph: 11
      weight: 1
      mapping:
        id: 21
        dict: {12: 23, 13: 24, 14: 25}
      attr_requirements:
        26: {source: 12}
      var_calc_instructions:
      - [step, 'random.uniform(0, 1)', application]
      daughter_graph:
        id: 22
        vertices:
        - id: 23
          attr: {x: 0, y: 0, label: "'a'"}
        - id: 24
          attr: {x: 1, y: 0}
        - id: 26
          attr: {x: 2, y: 0, size: "source.attr['label'] + str(step)"}
        edges:
        - id: 25
          vertex1: 23
          vertex2: 24
        - id: 27
          vertex1: 24
          vertex2: 26
result_graphs: {}
)yaml";

/// kBase with the one occurrence of `from` replaced by `to` (a test fails if there is not exactly one).
std::string variant(const std::string& from, const std::string& to) {
    std::string text = kBase;
    const std::size_t at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
        ADD_FAILURE() << "'" << from << "' is not in the base grammar exactly once";
        return text;
    }
    return text.replace(at, from.size(), to);
}

struct Refused {
    bool thrown = false;
    std::string file, where, message;
};

Refused parseError(const std::string& text) {
    Refused r;
    try {
        parseGraphGrammar(text, "bad.yml");
    } catch (const InputError& e) {
        r = {true, e.file(), e.where(), e.message()};
    }
    return r;
}

// One case: the text must be refused at `where` with a message containing every fragment.
void expectRefused(const std::string& text, const std::string& where, std::initializer_list<const char*> fragments) {
    const Refused r = parseError(text);
    ASSERT_TRUE(r.thrown) << "accepted";
    EXPECT_EQ(r.file, "bad.yml");
    EXPECT_EQ(r.where, where) << r.message;
    for (const char* f : fragments) EXPECT_NE(r.message.find(f), std::string::npos) << "'" << f << "' not in: " << r.message;
}

void expectRefused(const std::string& from, const std::string& to, const std::string& where, std::initializer_list<const char*> fragments) {
    expectRefused(variant(from, to), where, fragments);
}

TEST(GraphGrammarErrors, TheBaseGrammarReadsAndDerives) {
    const GraphGrammar g = parseGraphGrammar(kBase, "bad.yml");
    ASSERT_EQ(g.productions.size(), 1u);
    SeededDraws draws(5);
    const DeriveResult r = deriveGraph(g, 0, draws);
    EXPECT_EQ(r.steps, 10);
    EXPECT_EQ(r.graph.elements(), 3u + 2u * 10u);
}

// --- YAML itself ---------------------------------------------------------------------------

TEST(GraphGrammarErrors, YamlSyntaxError) {
    expectRefused("{all: 10}", "{all: 10", "19:12", {"YAML syntax", "',' or '}'"});
}

TEST(GraphGrammarErrors, TabIndentation) {
    expectRefused("    - id: 3\n", "    - id: 3\n\t", "8:1", {"tab"});
}

TEST(GraphGrammarErrors, EmptyFile) { expectRefused("", "1:1", {"the file is empty"}); }

TEST(GraphGrammarErrors, FileThatIsAList) { expectRefused("- host_graphs\n- productions\n", "1:1", {"must be a mapping", "a sequence"}); }

TEST(GraphGrammarErrors, NulByte) {
    const std::string text = variant("label: 'b'", std::string("label: 'b\0'", 11));
    expectRefused(text, "8:35", {"control"});
}

TEST(GraphGrammarErrors, InvalidUtf8) { expectRefused("label: 'b'", "label: '\xff\xfe'", "8:34", {"UTF-8"}); }

TEST(GraphGrammarErrors, AliasBomb) {
    std::string text = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
    for (char c = 'b'; c <= 'j'; ++c)
        text += std::string(1, c) + ": &" + c + " [*" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" +
                char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" +
                char(c - 1) + ", *" + char(c - 1) + "]\n";
    const Refused r = parseError(text + kBase);
    ASSERT_TRUE(r.thrown);
    EXPECT_NE(r.message.find("alias"), std::string::npos) << r.message;
    EXPECT_EQ(r.where.substr(0, 2), "5:") << r.message;  // e: copies 10^4 nodes 10 times, past 100,000
}

TEST(GraphGrammarErrors, DeepYamlNesting) {
    std::string text = variant("label: 'b'", "label: " + std::string(100, '[') + std::string(100, ']'));
    expectRefused(text, "8:91", {"nest"});
}

TEST(GraphGrammarErrors, HugeFile) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "graph_grammar_errors_huge.yml";
    {
        std::ofstream out(path, std::ios::binary);
        out << kBase << "extra: '";
        const std::string block(1 << 20, 'x');
        for (int i = 0; i < 17; ++i) out << block;
        out << "'\n";
    }
    try {
        readGraphGrammar(path.string());
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path.string());
        EXPECT_NE(e.message().find("more than the limit"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

// --- wrong types ---------------------------------------------------------------------------

TEST(GraphGrammarErrors, ListWhereMappingExpected) {
    expectRefused("{x: 0, y: 0, label: 'a'}", "[0, 0, 'a']", "6:13", {"host graph 'Start', vertex 2 attr", "must be a mapping", "a sequence"});
}

TEST(GraphGrammarErrors, StringId) { expectRefused("- id: 3\n", "- id: '3'\n", "7:11", {"host graph 'Start', vertex 3's id must be a whole number", "the string"}); }

TEST(GraphGrammarErrors, PriorityHigh) { expectRefused("priority: 0", "priority: high", "22:15", {"production 'Grow' priority", "whole number"}); }

TEST(GraphGrammarErrors, NegativeWeight) { expectRefused("weight: 1", "weight: -1", "39:15", {"production 'Grow', option 20", "weight"}); }

TEST(GraphGrammarErrors, XNotANumber) {
    expectRefused("{x: 1, y: 0, label: 'b'}", "{x: 'abc', y: 0, label: 'b'}", "8:17", {"vertex 3 x", "must be a number", "abc"});
}

// --- missing required keys -----------------------------------------------------------------

TEST(GraphGrammarErrors, NoHostGraphs) { expectRefused("host_graphs:", "extra:", "1:1", {"has no 'host_graphs'"}); }

TEST(GraphGrammarErrors, NoProductions) { expectRefused("productions:", "extra:", "1:1", {"has no 'productions'"}); }

TEST(GraphGrammarErrors, NoResultGraphs) { expectRefused("result_graphs: {}\n", "", "1:1", {"has no 'result_graphs'"}); }

TEST(GraphGrammarErrors, VertexWithoutId) {
    expectRefused("- id: 3\n      attr: {x: 1", "- attr: {x: 1", "7:7", {"host graph 'Start' vertex has no 'id'"});
}

TEST(GraphGrammarErrors, VertexWithoutX) { expectRefused("{x: 1, y: 0, label: 'b'}", "{y: 0, label: 'b'}", "8:13", {"vertex 3 has no 'x'"}); }

// --- ids -----------------------------------------------------------------------------------

TEST(GraphGrammarErrors, TwoVerticesWithOneId) {
    expectRefused("- id: 3\n", "- id: 2\n", "7:11", {"vertex 2: id 2 is already the id of host graph 'Start', vertex 2 (line 5)"});
}

TEST(GraphGrammarErrors, VertexAndProductionWithOneId) {
    expectRefused("id: 10\n", "id: 3\n", "21:9", {"production 'Grow': id 3 is already the id of host graph 'Start', vertex 3 (line 7)"});
}

TEST(GraphGrammarErrors, HostAndDaughterVertexWithOneId) {
    expectRefused("- id: 26\n", "- id: 3\n", "54:15", {"option 20 daughter graph, vertex 3: id 3 is already the id of host graph 'Start', vertex 3 (line 7)"});
}

TEST(GraphGrammarErrors, EdgeToAMissingVertex) {
    expectRefused("vertex1: 2\n", "vertex1: 99\n", "11:16", {"host graph 'Start', edge 4: vertex1 99 is not a vertex of this graph"});
}

TEST(GraphGrammarErrors, MappingFromAnElementNotInTheMotherGraph) {
    expectRefused("{12: 23,", "{99: 23,", "42:16", {"production 'Grow', option 20 mapping: 99 is not a vertex or edge of the mother graph"});
}

TEST(GraphGrammarErrors, MappingToAnElementNotInTheDaughterGraph) {
    expectRefused("13: 24,", "13: 98,", "42:28", {"option 20 mapping: 98 is not a vertex of the daughter graph"});
}

TEST(GraphGrammarErrors, MappingAMotherVertexToADaughterEdge) {
    expectRefused("13: 24,", "13: 27,", "42:28", {"27 is not a vertex of the daughter graph (the mother vertex 13 must map to one)"});
}

TEST(GraphGrammarErrors, VectorNamingAnEdge) {
    expectRefused("here: 12,", "here: 14,", "23:21", {"production 'Grow', vector 'here': 14 is an edge"});
}

TEST(GraphGrammarErrors, VectorNamingAMissingId) {
    expectRefused("along: [12, 13]", "along: [12, 99]", "23:37", {"vector 'along': 99 is not a vertex or edge of the production's mother graph"});
}

TEST(GraphGrammarErrors, RequirementForAMissingDaughterElement) {
    expectRefused("26: {source: 12}", "96: {source: 12}", "44:9", {"option 20 attr_requirements: 96 is not a vertex or edge of the daughter graph"});
}

TEST(GraphGrammarErrors, RequirementFromAMissingMotherElement) {
    expectRefused("26: {source: 12}", "26: {source: 97}", "44:22", {"option 20 attr_requirements: 97 is not a vertex or edge of the mother graph"});
}

TEST(GraphGrammarErrors, OptionOfAnotherMotherGraph) {
    expectRefused("mother_graph: 11\n", "mother_graph: 1\n", "38:21", {"option 20: mother_graph 1 is not this production's mother graph (11)"});
}

// --- unknown keys --------------------------------------------------------------------------

TEST(GraphGrammarErrors, UnknownTopLevelKey) {
    expectRefused("result_graphs: {}\n", "result_graphs: {}\nhost_graph: {}\n", "64:1", {"the file: unknown key 'host_graph'"});
}

TEST(GraphGrammarErrors, UnknownProductionKey) {
    expectRefused("priority: 0", "priorty: 0", "22:5", {"production 'Grow': unknown key 'priorty'"});
}

TEST(GraphGrammarErrors, UnknownOptionKey) { expectRefused("weight: 1", "wieght: 1", "39:7", {"option: unknown key 'wieght'"}); }

// --- expressions ---------------------------------------------------------------------------

// The daughter vertex 23's label: its quote at column 37 of line 51, the expression from 38.
const char* const kLabel = "label: \"'a'\"";

TEST(GraphGrammarErrors, UnknownNameInADaughterAttribute) {
    expectRefused(kLabel, "label: \"1 + foo\"", "51:42",
                  {"production 'Grow', option 20 daughter graph, vertex 23, attribute 'label'", "foo"});
}

TEST(GraphGrammarErrors, UnknownNameInAMatchCondition) {
    expectRefused("\"attr == 'a'\"", "\"atr == 'a'\"", "28:36", {"production 'Grow' mother graph, vertex 12, condition on 'label'", "atr"});
}

TEST(GraphGrammarErrors, UnknownFunction) { expectRefused(kLabel, "label: \"sqrt(2)\"", "51:38", {"vertex 23, attribute 'label'", "sqrt"}); }

TEST(GraphGrammarErrors, DunderImport) {
    expectRefused(kLabel, "label: \"__import__('os')\"", "51:38", {"vertex 23, attribute 'label'", "__import__"});
}

TEST(GraphGrammarErrors, OpenFile) { expectRefused(kLabel, "label: \"open('/etc/passwd')\"", "51:38", {"attribute 'label'", "open"}); }

TEST(GraphGrammarErrors, CallOutsideTheWhitelist) {
    expectRefused(kLabel, "label: \"os.system('x')\"", "51:38", {"attribute 'label'", "os"});
}

TEST(GraphGrammarErrors, Lambda) { expectRefused(kLabel, "label: \"lambda: 1\"", "51:38", {"attribute 'label'", "lambda"}); }

TEST(GraphGrammarErrors, ExpressionSyntaxError) { expectRefused(kLabel, "label: \"(1 + \"", "51:43", {"attribute 'label'"}); }

TEST(GraphGrammarErrors, DeepExpressionNesting) {
    expectRefused(kLabel, "label: \"" + std::string(200, '(') + "1" + std::string(200, ')') + "\"", "51:102",
                  {"attribute 'label'", "nest"});
}

TEST(GraphGrammarErrors, HundredKilobyteExpression) {
    std::string sum = "1";
    while (sum.size() < 100 * 1024) sum += " + 1";
    expectRefused(kLabel, "label: \"" + sum + "\"", "51:65574", {"attribute 'label'", "longer than 65536 bytes"});
}

TEST(GraphGrammarErrors, GlobalReadingAnotherGlobal) {
    expectRefused("'random.randint(1, 3)'", "'scale * 2'", "16:11", {"global variable 'count'", "scale"});
}

// --- options' variables and names ----------------------------------------------------------

TEST(GraphGrammarErrors, VariableWithTwoItems) {
    expectRefused("'random.uniform(0, 1)', application]", "'random.uniform(0, 1)']", "46:9",
                  {"option 20 var_calc_instructions: each is [name, expression, run | application]"});
}

TEST(GraphGrammarErrors, VariableKindSometimes) {
    expectRefused("'random.uniform(0, 1)', application]", "'random.uniform(0, 1)', sometimes]", "46:40",
                  {"'sometimes' is neither run nor application"});
}

TEST(GraphGrammarErrors, RequirementNamedLikeAVector) {
    expectRefused("26: {source: 12}", "26: {here: 12}", "44:14", {"option 20", "'here'"});
}

TEST(GraphReaderNames, AnElementsOwnRequirementHidesAGlobalOfTheSameName) {
    // The global 'scale' is 2.0; daughter vertex 26 names its requirement 'scale' too and reads
    // it as an element (a float has no .attr: the global would fail here).
    std::string text = variant("26: {source: 12}", "26: {scale: 12}");
    text.replace(text.find("source.attr"), 11, "scale.attr");
    const GraphGrammar g = parseGraphGrammar(text, "bad.yml");
    SeededDraws draws(2);
    DeriveLimits limits;
    limits.maxSteps = 1;
    const DeriveResult r = deriveGraph(g, 0, draws, limits);
    EXPECT_EQ(r.steps, 1);
}

TEST(GraphGrammarErrors, TooManyNamesInOneOption) {
    // Two vectors and 999 variables: the 999th is the 1001st name (names are bounded so that
    // reading stays linear; kMaxOptionNames).
    std::string variables;
    for (int i = 0; i < 999; ++i) variables += "      - [v" + std::to_string(i) + ", '1', application]\n";
    expectRefused("      - [step,", variables + "      - [step,", "1044:10", {"option 20: more than 1000 vectors, requirements for all and variables"});
}

TEST(GraphGrammarErrors, TooManyNamesInAllOptions) {
    // 1000 global variables, seen by each production's conditions and its option (2 + 1000 names
    // each): the 999th production passes 2,000,000 names.
    std::string globals = "global_vars:\n";
    for (int i = 0; i < 1000; ++i) globals += "  g" + std::to_string(i) + ": '1'\n";
    std::string productions = "productions:\n";
    for (int k = 0; k < 1000; ++k) {
        const std::string b = std::to_string(1000 + 10 * k);
        productions += "  P" + std::to_string(k) + ": {id: " + b + "1, mother_graph: {id: " + b + "2}, mappings: [{id: " + b + "3}]}\n";
    }
    const Refused r = parseError("host_graphs: {H: {id: 1}}\nresult_graphs: {}\n" + globals + productions);
    ASSERT_TRUE(r.thrown);
    EXPECT_EQ(r.where, "2003:9") << r.message;
    EXPECT_NE(r.message.find("production 'P998': the file's productions and options see more than 2000000 names"), std::string::npos)
        << r.message;
}

// --- errors while deriving -----------------------------------------------------------------

Refused deriveError(const std::string& text, const DeriveLimits& limits = {}) {
    Refused r;
    const GraphGrammar g = parseGraphGrammar(text, "bad.yml");
    try {
        SeededDraws draws(3);
        deriveGraph(g, 0, draws, limits);
    } catch (const InputError& e) {
        r = {true, e.file(), e.where(), e.message()};
    }
    return r;
}

TEST(GraphGrammarErrors, DivisionByZeroWhileDeriving) {
    const Refused r = deriveError(variant(kLabel, "label: \"1 / 0\""));
    ASSERT_TRUE(r.thrown);
    EXPECT_EQ(r.file, "bad.yml");
    EXPECT_EQ(r.where, "51:37");  // the scalar
    for (const char* f : {"production 'Grow'", "option 20", "daughter vertex 23", "'label'", "zero"})
        EXPECT_NE(r.message.find(f), std::string::npos) << f << " not in: " << r.message;
}

TEST(GraphGrammarErrors, NewPositionThatIsNotAVector) {
    const Refused r = deriveError(variant("attr: {x: 2, y: 0, size:", "attr: {x: 2, y: 0, .new_pos: '1 + 1', size:"));
    ASSERT_TRUE(r.thrown);
    EXPECT_EQ(r.where, "54:11");  // the vertex
    for (const char* f : {"production 'Grow'", "daughter vertex 26", ".new_pos", "a vector (Vec) expected"})
        EXPECT_NE(r.message.find(f), std::string::npos) << f << " not in: " << r.message;
}

TEST(GraphGrammarErrors, ElementLimit) {
    DeriveLimits limits;
    limits.maxElements = 10;  // 3, then 5, 7, 9, 11 at step 4
    const Refused r = deriveError(kBase, limits);
    ASSERT_TRUE(r.thrown);
    for (const char* f : {"passed 10 elements at step 4", "production 'Grow'", "element limit"})
        EXPECT_NE(r.message.find(f), std::string::npos) << f << " not in: " << r.message;
}

TEST(GraphGrammarErrors, StepLimitStopsAGrammarThatNeverEnds) {
    const GraphGrammar g = parseGraphGrammar(variant("{all: 10}", "{all: 0}"), "bad.yml");  // no limit in the file
    SeededDraws draws(3);
    DeriveLimits limits;
    limits.maxSteps = 25;
    const DeriveResult r = deriveGraph(g, 0, draws, limits);
    EXPECT_EQ(r.steps, 25);
    EXPECT_EQ(r.stop, DeriveResult::Stop::StepLimit);
    EXPECT_EQ(r.graph.elements(), 3u + 2u * 25u);
}

}  // namespace graph_grammar_errors_test
