// A `.pcg` graph made ready to translate: the main file with every included subgraph expanded
// in place (one instance per include node, its names prefixed `ID__`, its in/out gates kept as
// pass-through nodes wired to the include node's edges), every node's op resolved and its
// arguments as shapevo text, every port reference resolved and typed, the cyclic edges found
// (grammar/pcg/graph_order.hpp, nodes in file order) and every check made: unknown ops, ports and
// arguments, duplicate ids, type mismatches (naming both ports), unconnected inputs, unreached
// nodes, cycles with no conditional way out, missing and cyclic includes — each a located error;
// and the collective nodes grouped into gathers, each in its execution scope (pcg_collective.cpp).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "grammar/pcg/pcg_nodes.hpp"
#include "grammar/translation.hpp"

namespace shapevo::pcg {

struct FlatPort {
    std::string name;
    PortType type = PortType::Entity;  ///< resolved: never Same
    bool blocked = false;              ///< outputs: `block NODE.PORT`
    bool gate = false;
    bool collective = false;           ///< a list port (PortSpec::collective)
};

struct FlatNode {
    std::string name;     ///< as a user reads it: "frame", "door/frame" inside include node door
    std::string ident;    ///< for generated rule names: "frame", "door__frame"
    const NodeOp* op = nullptr;  ///< nullptr: a gate (passes its one input to its one output)
    bool gate = false, mainInput = false;
    std::string detail;   ///< for the diagram: "split x", "input gate (volume)"
    std::vector<FlatPort> inputs, outputs;
    std::vector<std::string> args;   ///< per op ArgSpec (Sizes: empty)
    std::vector<std::string> sizes;  ///< split sizes
    Location where;
    Location includeAt;        ///< an included graph's input gate: its include node's place
    std::string includeName;   ///< and its id
    std::uint32_t scope = 0;   ///< its execution scope: FlatGraph::scopes (0: the main graph's)
    std::int32_t chain = -1;   ///< a collective node: its gather, FlatGraph::chains
};

/// An execution scope (PCGR §3.7): the main graph, or one include node's instance of its file,
/// which runs to completion per entity reaching one of its input gates.
struct ExecutionScope {
    std::string ident;     ///< "" for the main graph, else the instance's prefix without its "__"
    std::string name;      ///< for messages: the graph's name, or "house (house.pcg)"
    std::int32_t parent = -1;
    std::vector<std::uint32_t> chains;  ///< its gathers, in the order they run (filled by the checks)
};

/// A chain of collective nodes, each fed only by the one before: one `gather` of its scope, the
/// first node's input the list, the steps in order, the last node's outputs its routes.
struct ListChain {
    std::vector<std::uint32_t> nodes;
    std::string list;  ///< the list's name in the translation: pcg_l_IDENT of the first node
    std::uint32_t scope = 0;
};

struct FlatEdge {
    std::uint32_t from = 0, fromPort = 0, to = 0, toPort = 0;
    Location where;
    bool cyclic = false;
};

/// A graph value: a `param` with its prior, or an include's bound param (a `let`).
struct GraphValue {
    std::string name;
    std::string declaration;  ///< "param NAME = PRIOR" or "let NAME = EXPR"
    Location where;
};

struct GraphAttr {
    std::string name, value;
    Location where;
};

struct FlatGraph {
    std::string name;  ///< the main file's `graph NAME`
    Location nameAt;
    std::vector<FlatNode> nodes;     ///< file order, an instance's nodes where its include node stands
    std::vector<FlatEdge> edges;     ///< file order likewise
    std::vector<GraphValue> values;  ///< declaration order (an instance's after its includer's)
    std::vector<GraphAttr> attrs;
    std::vector<GraphAttr> carried;  ///< the main file's `carry` declarations (graph-wide: includes read and set them)
    std::vector<std::string> files;  ///< included files, relative to the main file's folder
    std::vector<ExecutionScope> scopes;  ///< [0] the main graph's, then one per include node
    std::vector<ListChain> chains;       ///< filled by checkPcgGraph
};

/// Read and check the graph file `path` (its text given) with its includes.
/// @throw InputError at file:line:column of the file with the problem.
FlatGraph buildPcgGraph(const std::string& text, const std::string& path);

/// The whole-graph checks (pcg_graph_checks.cpp), in this order: every input connected, the cyclic
/// edges (§3.5) marked, every node reached from an input gate, port types resolved (an output of
/// type Same takes its node's input type) and checked on every edge, every cycle's way out, then
/// the collective nodes' gathers (checkCollectiveNodes).
/// @throw InputError at the place of the first problem.
void checkPcgGraph(FlatGraph& g);

/// Group the collective nodes into chains (FlatGraph::chains), order each scope's gathers, and
/// check that every list stays in its scope and its gene (pcg_collective.cpp).
/// @throw InputError at the place of the first problem.
void checkCollectiveNodes(FlatGraph& g);

}  // namespace shapevo::pcg
