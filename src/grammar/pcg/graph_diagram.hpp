// GraphDiagram: the picture of a procedural content graph or of a grammar's generator graph as
// plain data, in PCGR's notation (pcgr/NOTES.md §4.6): nodes with ports — single (drawn round) or
// collective (square), blocked (filled), gates (thick) — and directed edges with flags: cyclic
// (§3.5; drawn dashed), an inline call (no gene boundary) or blocked. Every front end builds one
// (grammar/grammar_diagram.hpp for .grammar and .rule files, grammar/pcg/pcg_front_end.hpp for
// .pcg files); report/diagram_writer.hpp draws it.
// numberDiagram() fills the §3.4 / §3.5 results (cyclic edges, topological numbers, loop nodes)
// from the nodes and edges alone, so every front end's picture follows the same order.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace shapevo::pcg {

enum class PortKind : std::uint8_t {
    Single,      ///< one entity per round (drawn round)
    Collective,  ///< the whole list at once (drawn square)
};

struct DiagramPort {
    std::string name;
    bool input = true;       ///< an input port (else an output)
    PortKind kind = PortKind::Single;
    bool blocked = false;    ///< discards what reaches it (drawn filled)
    bool gate = false;       ///< a port of the enclosing graph's node (drawn thick)
};

struct DiagramNode {
    std::string name;                ///< its name in the file (a rule, a rule instance, a node id)
    std::string detail;              ///< a second line: what it is ("start rule; 3 parameters")
    std::vector<DiagramPort> ports;  ///< inputs and outputs, in the order drawn
    bool start = false;              ///< where derivation begins (drawn with a bold border)
    // Filled by numberDiagram():
    std::uint32_t order = 0;         ///< §3.4 topological number, 0 first
    bool loop = false;               ///< lies on a cycle (Fig 3's `*`)
};

enum class EdgeKind : std::uint8_t {
    Flow,    ///< a .pcg edge: entities pass from port to port
    Child,   ///< a grammar's child slot: a gene boundary
    Inline,  ///< a grammar's inline rule call: the callee runs inside the caller's gene
};

struct DiagramEdge {
    std::uint32_t from = 0, to = 0;           ///< node indices
    std::int32_t fromPort = -1, toPort = -1;  ///< port indices in those nodes (-1: the node itself)
    std::string label;                        ///< e.g. "slot 1 · edge 4 · p 0.5"
    EdgeKind kind = EdgeKind::Flow;
    bool blocked = false;                     ///< discards what passes
    bool cyclic = false;                      ///< filled by numberDiagram(): §3.5 marks it
};

struct GraphDiagram {
    std::string title;                ///< the file it shows
    std::string nodeNoun = "nodes";   ///< what its nodes are, plural, for a summary line: a grammar's are "rules"
    std::vector<DiagramNode> nodes;   ///< in file order (the §3.4 tie order)
    std::vector<DiagramEdge> edges;   ///< in file order (the §3.5 search order)
};

/// Fill every node's order and loop mark and every edge's cyclic mark (grammar/pcg/graph_order.hpp).
void numberDiagram(GraphDiagram& diagram);

/// Counts for a summary line.
struct DiagramCounts {
    std::size_t nodes = 0, edges = 0, cyclicEdges = 0, loopNodes = 0;
};
DiagramCounts countDiagram(const GraphDiagram& diagram);

}  // namespace shapevo::pcg
