// Every malformed `.pcg` graph file (grammars/pcg/README.md) is rejected with an InputError whose
// text is exactly `file:LINE:COLUMN: message`, at the place in the user's own .pcg file (never a
// line of its translation), the message saying what is wrong. Each case is written into a fresh
// folder as bad.pcg, with the other graph files it includes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace pcg_malformed_test_helpers {

struct MalformedGraph {
    const char* name;                                        ///< test name suffix: what is wrong
    std::string text;                                        ///< bad.pcg
    std::string where;                                       ///< expected "FILE:LINE:COL" (file name only)
    std::string message;                                     ///< the expected message, exactly (ending "...": its start)
    std::vector<std::pair<std::string, std::string>> files;  ///< other files in the folder
};

std::ostream& operator<<(std::ostream& os, const MalformedGraph& m) { return os << m.name; }

// Lines 1-2 of most cases; the case's own lines start at line 3.
std::string graph(const std::string& lines) { return "graph G\nin start : volume\n" + lines; }

const std::vector<MalformedGraph>& graphCases() {
    static const std::vector<MalformedGraph> all = {
        // --- nodes and their operations -------------------------------------------------
        {"UnknownNodeOperation", graph("node a = boxx()\nstart -> a\n"), "bad.pcg:3:10",
         "unknown node operation 'boxx': expected one of box, cylinder, cone, sphere, paraboloid, roof, extrude, translate, rotate, "
         "scale, size, color, split, repeat, copy, comp, lot_rect, if, set, chance, order_by, reverse, shuffle, group_by, cluster, unify, merge, ungroup, aggregate, amount_filter, filter or include \"FILE.pcg\""},
        {"DuplicateNodeId", graph("node a = box()\nnode a = sphere()\nstart -> a\n"), "bad.pcg:4:6",
         "node id 'a' is used twice (first at line 3)"},
        {"NodeIdSameAsAGate", graph("node start = box()\n"), "bad.pcg:3:6", "node id 'start' is used twice (first at line 2)"},
        // --- arguments ------------------------------------------------------------------
        {"UnknownArgumentName", graph("node a = translate(w: 1)\nstart -> a\n"), "bad.pcg:3:20",
         "translate has no argument 'w' (its arguments: x, y, z)"},
        {"MissingArgument", graph("node a = rotate(x)\nstart -> a\n"), "bad.pcg:3:10", "rotate needs argument 'angle'"},
        {"CopyWithoutCount", graph("node c = copy()\nstart -> c\n"), "bad.pcg:3:10", "copy needs argument 'count'"},
        {"TooManyArguments", graph("node a = rotate(x, 1, 2)\nstart -> a\n"), "bad.pcg:3:23",
         "rotate takes 2 arguments, this node gives 3"},
        {"ArgumentGivenTwice", graph("node a = translate(x: 1, x: 2)\nstart -> a\n"), "bad.pcg:3:26",
         "argument 'x' of translate is given twice"},
        {"PositionalAfterNamed", graph("node a = translate(y: 1, 2)\nstart -> a\n"), "bad.pcg:3:26",
         "a positional argument after a named one (translate)"},
        {"BadAxis", graph("node a = split(w, 1, ~1)\nstart -> a\n"), "bad.pcg:3:16",
         "argument 'axis' of split is one of x, y, z, not 'w'"},
        {"BadRoofKind", graph("node a = roof(flat)\nstart -> a\n"), "bad.pcg:3:15",
         "argument 'kind' of roof is one of gable, hip, pyramid, not 'flat'"},
        {"SplitWithoutSizes", graph("node a = split(x)\nstart -> a\n"), "bad.pcg:3:10",
         "split needs at least one size: split(x, 1, ~2, 1)"},
        {"RepeatWithCountAndSize", graph("node a = repeat(x, count: 3, size: 2)\nnode b = box()\nstart -> a\na -> b\n"), "bad.pcg:3:6",
         "repeat takes either count: N or size: SIZE (S, ~S or 'S), not both or neither"},
        {"ExpressionErrorAtItsNodeLine", graph("node a = translate(x: nosuch)\nstart -> a\n"), "bad.pcg:3:6",
         "unknown name 'nosuch': expected a parameter declared above in this rule, an argument of the rule, a let value, an attr, "
         "a carried attribute, scope.size, scope.origin, scope.axis.x (.y, .z), parent.size, piece.index, piece.count, pi, or a function (min max abs "
         "sin cos sqrt floor atan2 length dot distance) (in its translation to the shapevo language:   "
         "translate (nosuch, 0, 0))"},
        // --- ports and edges ------------------------------------------------------------
        {"UnknownPort", graph("node a = box()\nstart -> a.inn\n"), "bad.pcg:4:10",
         "node 'a' (box) has no input port 'inn' (its inputs: in)"},
        {"UnknownNodeInEdge", graph("start -> nowhere\n"), "bad.pcg:3:10", "unknown node 'nowhere'"},
        {"PortNotNamedWhereThereAreSeveral", graph("node i = if(1)\nnode b = box()\nstart -> i\ni -> b\n"), "bad.pcg:6:1",
         "node 'i' (if) has 2 output ports (true, false): name one, i.PORT"},
        {"TypeMismatchNamesBothPorts", graph("node c = comp()\nnode b = box()\nstart -> c\nc.top -> b\n"), "bad.pcg:6:1",
         "cannot connect c.top (flat) to b.in (volume): box takes a volume"},
        {"GateWithAPort", graph("node a = box()\nstart.out -> a\n"), "bad.pcg:4:1",
         "'start' is a gate, a port itself: write start without a port"},
        {"EdgeFromAnOutputGate", graph("out done : volume\nnode a = box()\nstart -> a\ndone -> a\n"), "bad.pcg:6:1",
         "'done' is an output gate: edges end there (... -> done)"},
        {"MissingArrow", graph("node a = box()\nstart a\n"), "bad.pcg:4:7",
         "expected '->' after start (statements: graph, attr, carry, param, in, out, node, block; edges: SRC.PORT -> DST.PORT), found 'a'"},
        {"UnconnectedRequiredInput", graph("node a = box()\nnode b = box()\nstart -> a\n"), "bad.pcg:4:6",
         "input 'in' of node 'b' (box) is not connected: an edge must lead to it"},
        {"NodeNeverReached", graph("node a = box()\nnode b = translate(x: 1)\nstart -> a\nb -> b\n"), "bad.pcg:4:6",
         "node 'b' is never reached: no path leads to it from an input gate"},
        {"CycleWithNoWayOut", graph("node a = translate(x: 1)\nnode b = box()\nstart -> a\na -> b\nb -> a\n"), "bad.pcg:7:1",
         "a cycle with no way out (through a, b): it would never end; put an `if` or a `chance` node on it"},
        // --- collective nodes (square ports: send and gather) ------------------------------
        {"CollectiveNodeFedByNothing", graph("node o = order_by(scope.size.y)\nnode b = box()\nstart -> b\n"), "bad.pcg:3:6",
         "collective input 'in' of node 'o' (order_by) is not connected: it gathers what edges send to it, and none does"},
        {"OrderByWithoutAKey", graph("node o = order_by()\nstart -> o\n"), "bad.pcg:3:10",
         "order_by needs at least one key: order_by(scope.size.y, scope.origin.x)"},
        {"OrderByKeyNamed", graph("node o = order_by(keys: scope.size.y)\nstart -> o\n"), "bad.pcg:3:19",
         "order_by keys are positional: order_by(scope.size.y, scope.origin.x)"},
        {"AmountFilterWithoutCount", graph("node f = amount_filter(from: 1)\nstart -> f\n"), "bad.pcg:3:10",
         "amount_filter needs argument 'count'"},
        {"ShuffleWithoutItsDraw", graph("node s = shuffle()\nstart -> s\n"), "bad.pcg:3:10", "shuffle needs argument 'u'"},
        {"UnknownCollectivePort", graph("node f = amount_filter(count: 1)\nnode b = box()\nstart -> f\nf.second -> b\n"), "bad.pcg:6:1",
         "node 'f' (amount_filter) has no output port 'second' (its outputs: first, rest)"},
        {"TwoRoutesNamedAlone", graph("node f = filter(scope.size.y > 1)\nnode b = box()\nstart -> f\nf -> b\n"), "bad.pcg:6:1",
         "node 'f' (filter) has 2 output ports (true, false): name one, f.PORT"},
        {"CollectiveOutputTypeMismatch",
         graph("node c = comp()\nnode o = order_by(scope.size.x)\nnode b = box()\nstart -> c\nc.side -> o\no -> b\n"), "bad.pcg:8:1",
         "cannot connect o.out (flat) to b.in (volume): box takes a volume"},
        {"ListOutOfAnIncludedGraphIntoACollectiveNode",
         graph("node s = include \"sub.pcg\"\nnode r = reverse()\nnode b = box()\nstart -> s\ns -> r\nr -> b\n"), "sub.pcg:6:1",
         "the list out of s/o.out would go through gate 's/list' into 'r' (reverse) of another execution scope: a list stays in "
         "the graph that gathers it; let a node with single ports take its entities first",
         {{"sub.pcg", "graph Sub\nin lot : volume\nout list : volume\nnode o = order_by(scope.size.y)\nlot -> o\no -> list\n"}}},
        {"ListIntoAnIncludedGraphsCollectiveNode", graph("node o = order_by(scope.size.y)\nnode s = include \"sub.pcg\"\nstart -> o\no -> s\n"),
         "bad.pcg:6:1",
         "the list out of o.out would go through gate 's/items' into 's/r' (reverse) of another execution scope: a list stays in "
         "the graph that gathers it; let a node with single ports take its entities first",
         {{"sub.pcg", "graph Sub\nin items : volume\nnode r = reverse()\nnode b = box()\nitems -> r\nr -> b\n"}}},
        {"SendFromAnotherGeneThroughACyclicEdge",
         graph("node b = box()\nnode up = translate(y: 1)\nnode more = chance(0.5)\nnode o = order_by(scope.origin.y)\n"
               "node s = sphere()\nstart -> b\nb -> up\nup -> more\nmore.yes -> b\nb -> o\no -> s\n"),
         "bad.pcg:12:1",
         "the edge from 'b' sends to 'o' (order_by) from another gene (after the cyclic edge more -> b), but 'o' (order_by) "
         "gathers in graph G: a list never crosses a gene boundary; put the collective nodes in a graph included after it"},
        {"SendFromAChanceNodesGene", graph("node c = chance(0.5)\nnode o = reverse()\nnode b = box()\nstart -> c\nc.yes -> o\no -> b\n"),
         "bad.pcg:7:1",
         "the edge from 'c' sends to 'o' (reverse) from another gene (after the chance node 'c'), but 'o' (reverse) gathers in "
         "graph G: a list never crosses a gene boundary; put the collective nodes in a graph included after it"},
        {"ARouteBackIntoItsOwnListRoundALoop",
         graph("node o = order_by(scope.size.y)\nnode f = amount_filter(count: 1)\nnode b = box()\nnode small = if(scope.size.y > 1)\n"
               "start -> o\no -> f\nf.first -> b\nf.rest -> small\nsmall.true -> o\n"),
         "bad.pcg:11:1",
         "the edge from 'small' sends to 'o' (order_by) from another gene (after the cyclic edge small -> o), but 'o' (order_by) "
         "gathers in graph G: a list never crosses a gene boundary; put the collective nodes in a graph included after it"},
        {"SendFromAChanceInsideAnIncludedGraph", graph("node s = include \"sub.pcg\"\nstart -> s\n"), "sub.pcg:7:1",
         "the edge from 's/c' sends to 's/o' (reverse) from another gene (after the chance node 's/c'), but 's/o' (reverse) "
         "gathers in each run of s (sub.pcg): a list never crosses a gene boundary; put the collective nodes in a graph included "
         "after it",
         {{"sub.pcg", "graph Sub\nin lot : volume\nnode c = chance(0.5)\nnode o = reverse()\nnode b = box()\nlot -> c\nc.yes -> o\no -> b\n"}}},
        {"ClusterWithoutK", graph("node o = cluster(by: scope.origin)\nnode b = box()\nstart -> o\no -> b\n"), "bad.pcg:3:10",
         "cluster needs argument 'k'"},
        {"UnknownAggregateKind", graph("node o = aggregate(name: m, kind: mean, value: 1)\nnode b = box()\nstart -> o\no -> b\n"),
         "bad.pcg:3:35", "argument 'kind' of aggregate is one of min, max, avg, sum, group_index, not 'mean'"},
        {"GroupByWithoutKey", graph("node o = group_by()\nnode b = box()\nstart -> o\no -> b\n"), "bad.pcg:3:10",
         "group_by needs at least one key: group_by(scope.size.y, scope.origin.x)"},
        {"CarriedAttributeDeclaredInAnIncludedGraph", graph("node h = include \"sub.pcg\"\nstart -> h\n"), "sub.pcg:2:7",
         "carried attribute 'level' is declared in an included graph: declare carried attributes in the main graph, which every "
         "included graph reads and sets by name",
         {{"sub.pcg", "graph Sub\ncarry level = 0\nin lot : volume\nnode b = box()\nlot -> b\n"}}},
        {"SetOfAnUndeclaredAttribute", graph("node s = set(name: level, value: 1)\nnode b = box()\nstart -> s\ns -> b\n"), "bad.pcg:3:6",
         "'level' is not a carried attribute: declare it at the top level first (carry level = VALUE) (in its translation to the "
         "shapevo language:   set level = 1)"},
        {"MisspeltSortDirection", graph("node o = order_by(scope.size.y dsc)\nnode b = box()\nstart -> o\no -> b\n"), "bad.pcg:3:6",
         "expected a list operation (order by, reverse, shuffle, let NAME = min|max|avg|sum(E), group by, cluster, unify, merge, "
         "ungroup) or a route (each, keep first, where) in 'gather pcg_l_o', found 'dsc' (in its translation to the shapevo language:     order by scope.size.y dsc)"},
        // --- declarations ---------------------------------------------------------------
        {"NoGraphName", "in start : volume\n", "bad.pcg:1:1", "no graph name: a .pcg file starts with `graph NAME`"},
        {"NoInputGate", "graph G\n", "bad.pcg:1:7",
         "graph G has no input gate: write `in NAME : volume` (it receives the start scope)"},
        {"UnknownGateType", "graph G\nin start : solid\n", "bad.pcg:2:12", "unknown port type 'solid': expected volume, flat or entity"},
        {"NameDeclaredTwice", "graph G\nattr w = 1\nparam w = uniform(0, 1)\nin start : volume\n", "bad.pcg:3:7",
         "'w' is declared twice (first at line 2)"},
        {"UnbalancedBracketInAttr", "graph G\nattr w = (1 + 2\nin start : volume\n", "bad.pcg:4:1",
         "expected a closing bracket, found end of file"},
        // --- includes -------------------------------------------------------------------
        {"MissingInclude", graph("node h = include \"nothere.pcg\"\nstart -> h\n"), "bad.pcg:3:18",
         "cannot open graph file 'nothere.pcg' (looked for ..."},
        {"CyclicInclude", graph("node h = include \"sub.pcg\"\nstart -> h\n"), "sub.pcg:3:21",
         "include cycle: bad.pcg -> sub.pcg -> bad.pcg",
         {{"sub.pcg", "graph Sub\nin lot : volume\nnode back = include \"bad.pcg\"\nlot -> back\n"}}},
        {"PositionalIncludeArgument", graph("node h = include \"sub.pcg\"(2)\nstart -> h\n"), "bad.pcg:3:28",
         "include arguments are named: include \"sub.pcg\"(NAME: VALUE)",
         {{"sub.pcg", "graph Sub\nparam w = uniform(1, 2)\nin lot : volume\nnode b = box()\nlot -> b\n"}}},
        {"IncludeArgumentNotAParam", graph("node h = include \"sub.pcg\"(v: 2)\nstart -> h\n"), "bad.pcg:3:28",
         "sub.pcg has no param or attr 'v'",
         {{"sub.pcg", "graph Sub\nparam w = uniform(1, 2)\nin lot : volume\nnode b = box()\nlot -> b\n"}}},
        {"ProblemInsideAnIncludedFileIsAtItsLine", graph("node h = include \"sub.pcg\"\nstart -> h\n"), "sub.pcg:4:10",
         "unknown node operation 'bx': expected one of box, cylinder, cone, sphere, paraboloid, roof, extrude, translate, rotate, "
         "scale, size, color, split, repeat, copy, comp, lot_rect, if, set, chance, order_by, reverse, shuffle, group_by, cluster, unify, merge, ungroup, aggregate, amount_filter, filter or include \"FILE.pcg\"",
         {{"sub.pcg", "graph Sub\nin lot : volume\nlot -> b\nnode b = bx()\n"}}},
        {"UnconnectedIncludeInput", graph("node h = include \"sub.pcg\"\nnode a = box()\nstart -> a\n"), "bad.pcg:3:6",
         "input 'lot' of node 'h' (an included graph) is not connected: an edge must lead to it",
         {{"sub.pcg", "graph Sub\nin lot : volume\nnode b = box()\nlot -> b\n"}}},
    };
    return all;
}

}  // namespace pcg_malformed_test_helpers

using namespace pcg_malformed_test_helpers;

class GraphFileMalformed : public ::testing::TestWithParam<MalformedGraph> {};

TEST_P(GraphFileMalformed, IsRejectedAtItsPlaceInTheGraphFileWithItsMessage) {
    const MalformedGraph& m = GetParam();
    test::TempDir dir;
    test::writeFile(dir.file("bad.pcg"), m.text);
    for (const auto& [name, text] : m.files) test::writeFile(dir.file(name), text);
    try {
        loadGrammar(dir.file("bad.pcg"));
        FAIL() << "expected InputError for:\n" << m.text;
    } catch (const InputError& e) {
        EXPECT_EQ(std::filesystem::path(e.file()).filename().string() + ":" + e.where(), m.where) << e.what();
        const std::string_view expected = m.message;
        if (expected.ends_with("..."))  // the rest names a temporary folder
            EXPECT_EQ(e.message().substr(0, expected.size() - 3), expected.substr(0, expected.size() - 3)) << e.what();
        else
            EXPECT_EQ(e.message(), m.message) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(GraphCases, GraphFileMalformed, ::testing::ValuesIn(graphCases()),
                         [](const ::testing::TestParamInfo<MalformedGraph>& info) { return std::string(info.param.name); });

}  // namespace shapevo
