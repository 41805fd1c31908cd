// The order of a procedural content graph (PCGR, procedural-content-graphs.txt §3.4 and §3.5), as
// a pure function of its nodes (in file order) and directed edges (in file order):
// - cyclic edges, found exactly as §3.5 says: every edge starts "unvisited" and "noncyclic"; from
//   every node in file order a depth-first iteration runs with an empty list of visited nodes; at
//   a node, the node joins the list, and each of its still "unvisited" outgoing edges (in edge
//   order, checked when its turn comes) is marked "cyclic" if its destination is in the list, else
//   "visited" and followed with a copy of the list. The marks persist from one start node to the
//   next. (The list at a node is exactly the path from the start to it, so it is kept as one flag
//   per node on the current path.) Removing the cyclic edges leaves an acyclic graph.
// - topological numbers (§3.4), ignoring the cyclic edges: the source nodes (no incoming non-cyclic
//   edge) first, in file order; then, repeatedly, the node first in file order among those whose
//   incoming non-cyclic edges all come from numbered nodes. So order(u) < order(v) on every
//   non-cyclic edge u -> v, and the numbers are 0, 1, ..., N-1.
// - loop nodes: the nodes that lie on a cycle (a node reaches itself through one edge or more, a
//   self-loop included): Fig 3's `*`, the nodes that run more than once.
// Ports do not change the result (the search runs over nodes); edges carry them for the front ends.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace shapevo::pcg {

/// A directed edge from node `from` to node `to` (indices into the node list), optionally from
/// output port `fromPort` to input port `toPort` of those nodes (-1: the node itself).
struct OrderEdge {
    std::uint32_t from = 0, to = 0;
    std::int32_t fromPort = -1, toPort = -1;
};

struct GraphOrder {
    std::vector<std::uint8_t> cyclic;  ///< per edge: 1 if §3.5 marks it cyclic
    std::vector<std::uint32_t> order;  ///< per node: its topological number (0 first)
    std::vector<std::uint8_t> loop;    ///< per node: 1 if it lies on a cycle
};

/// §3.5's cyclic edges of a graph of `nodeCount` nodes. @throw std::out_of_range for an edge
/// naming a node >= nodeCount.
std::vector<std::uint8_t> findCyclicEdges(std::size_t nodeCount, std::span<const OrderEdge> edges);

/// §3.4's topological numbers over the edges not marked in `cyclic` (one flag per edge), which
/// must leave an acyclic graph (findCyclicEdges' do). @throw std::logic_error if they do not.
std::vector<std::uint32_t> topologicalNumbers(std::size_t nodeCount, std::span<const OrderEdge> edges,
                                              std::span<const std::uint8_t> cyclic);

/// The nodes on a cycle (strongly connected components of two nodes or more, and self-loops).
std::vector<std::uint8_t> loopNodes(std::size_t nodeCount, std::span<const OrderEdge> edges);

/// All three.
GraphOrder graphOrder(std::size_t nodeCount, std::span<const OrderEdge> edges);

}  // namespace shapevo::pcg
