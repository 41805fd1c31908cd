// HostGraph: the graph a derivation rewrites — attributed vertices (with a position) and edges
// whose ends are ordered and may be empty (a dangling edge is legal and counts as an element).
// Element ids are indices that are never reused: a deleted element stays as a tombstone, so an id
// names one element for the whole derivation and every iteration order is the order of creation
// (no address-dependent order anywhere: one seed, one graph, on every machine). A tombstone keeps
// its attributes (the expressions of the step that deleted it read them).
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "graph/value.hpp"

namespace shapevo::graph {

using ElementId = std::uint32_t;
inline constexpr ElementId kNoVertex = std::numeric_limits<ElementId>::max();

struct HostVertex {
    AttrMap attrs;          // every attribute but x and y (which live in `position`)
    Vec2 position;
    std::int64_t generation = 0;
    bool alive = true;
    std::vector<ElementId> edges;  // incident live edges, in the order they were attached
    // Lineage (lineage_key.hpp), for keyed derivations: the element's key, the seed and event
    // (step, 0 = the start) of the event that made it.
    std::uint64_t key = 0, seed = 0;
    std::uint32_t birth = 0;
};

struct HostEdge {
    AttrMap attrs;
    ElementId vertex1 = kNoVertex, vertex2 = kNoVertex;  // kNoVertex: a dangling end
    std::int64_t generation = 0;
    bool alive = true;
    std::uint64_t key = 0, seed = 0;  // lineage, as HostVertex's
    std::uint32_t birth = 0;
};

class HostGraph {
public:
    ElementId addVertex(Vec2 position, AttrMap attrs, std::int64_t generation);
    /// Adds an edge between two live vertices (or kNoVertex for a dangling end).
    ElementId addEdge(ElementId v1, ElementId v2, AttrMap attrs, std::int64_t generation);
    /// Deletes a vertex; its edges stay, with that end set to kNoVertex.
    void removeVertex(ElementId v);
    void removeEdge(ElementId e);
    /// Moves one end of an edge (end 0: vertex1, 1: vertex2) to another live vertex or kNoVertex.
    void setEnd(ElementId e, int end, ElementId v);
    /// Room for `vertices` and `edges` in all, so that adding up to that many moves no stored
    /// element (ElementRefs taken before stay valid). Grows geometrically.
    void reserve(std::size_t vertices, std::size_t edges) {
        if (vertices > vertices_.capacity()) vertices_.reserve(std::max(vertices, 2 * vertices_.capacity()));
        if (edges > edges_.capacity()) edges_.reserve(std::max(edges, 2 * edges_.capacity()));
    }

    const std::vector<HostVertex>& vertices() const { return vertices_; }
    const std::vector<HostEdge>& edges() const { return edges_; }
    HostVertex& vertex(ElementId v) { return vertices_[v]; }
    HostEdge& edge(ElementId e) { return edges_[e]; }
    const HostVertex& vertex(ElementId v) const { return vertices_[v]; }
    const HostEdge& edge(ElementId e) const { return edges_[e]; }

    std::size_t liveVertices() const { return liveVertices_; }
    std::size_t liveEdges() const { return liveEdges_; }
    /// Live edges with at least one empty end.
    std::size_t danglingEdges() const;
    /// The paper's "elements": live vertices + live edges (dangling ones included).
    std::size_t elements() const { return liveVertices_ + liveEdges_; }

private:
    std::vector<HostVertex> vertices_;
    std::vector<HostEdge> edges_;
    std::size_t liveVertices_ = 0, liveEdges_ = 0;
};

/// The drawing (z-)order of the original's exporter (seen in its SVGs): breadth-first layers from
/// the oldest unvisited live vertex — a layer's vertices (in discovery order), then each of their
/// incident edges not yet listed (vertex by vertex, in attachment order), whose far ends not yet
/// seen form the next layer; again from the oldest unvisited vertex for the next component; edges
/// with no end last, oldest first. Each entry: {isVertex, id}.
struct DrawItem {
    bool isVertex;
    ElementId id;
};
std::vector<DrawItem> breadthFirstOrder(const HostGraph& g);

}  // namespace shapevo::graph
