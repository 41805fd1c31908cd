// HostGraph's edits: ids are never reused, incidence lists stay in attachment order.
#include "graph/host_graph.hpp"

#include <algorithm>

namespace shapevo::graph {

ElementId HostGraph::addVertex(Vec2 position, AttrMap attrs, std::int64_t generation) {
    HostVertex v;
    v.attrs = std::move(attrs);
    v.position = position;
    v.generation = generation;
    vertices_.push_back(std::move(v));
    ++liveVertices_;
    return ElementId(vertices_.size() - 1);
}

ElementId HostGraph::addEdge(ElementId v1, ElementId v2, AttrMap attrs, std::int64_t generation) {
    const ElementId id = ElementId(edges_.size());
    HostEdge e;
    e.attrs = std::move(attrs);
    e.vertex1 = v1;
    e.vertex2 = v2;
    e.generation = generation;
    edges_.push_back(std::move(e));
    ++liveEdges_;
    if (v1 != kNoVertex) vertices_[v1].edges.push_back(id);
    if (v2 != kNoVertex && v2 != v1) vertices_[v2].edges.push_back(id);
    return id;
}

namespace {

void detach(std::vector<ElementId>& list, ElementId e) {
    const auto it = std::find(list.begin(), list.end(), e);
    if (it != list.end()) list.erase(it);
}

}  // namespace

void HostGraph::removeVertex(ElementId v) {
    HostVertex& vertex = vertices_[v];
    if (!vertex.alive) return;
    for (ElementId e : vertex.edges) {
        HostEdge& edge = edges_[e];
        if (edge.vertex1 == v) edge.vertex1 = kNoVertex;
        if (edge.vertex2 == v) edge.vertex2 = kNoVertex;
    }
    vertex.edges.clear();
    vertex.alive = false;  // its attributes stay: a step's expressions may still read them
    --liveVertices_;
}

void HostGraph::removeEdge(ElementId e) {
    HostEdge& edge = edges_[e];
    if (!edge.alive) return;
    if (edge.vertex1 != kNoVertex) detach(vertices_[edge.vertex1].edges, e);
    if (edge.vertex2 != kNoVertex) detach(vertices_[edge.vertex2].edges, e);
    edge.vertex1 = edge.vertex2 = kNoVertex;
    edge.alive = false;
    --liveEdges_;
}

void HostGraph::setEnd(ElementId e, int end, ElementId v) {
    HostEdge& edge = edges_[e];
    ElementId& slot = end == 0 ? edge.vertex1 : edge.vertex2;
    const ElementId other = end == 0 ? edge.vertex2 : edge.vertex1;
    if (slot == v) return;
    if (slot != kNoVertex && slot != other) detach(vertices_[slot].edges, e);
    slot = v;
    if (v != kNoVertex && v != other) vertices_[v].edges.push_back(e);
}

std::size_t HostGraph::danglingEdges() const {
    std::size_t n = 0;
    for (const HostEdge& e : edges_)
        if (e.alive && (e.vertex1 == kNoVertex || e.vertex2 == kNoVertex)) ++n;
    return n;
}

}  // namespace shapevo::graph
