// numberDiagram and countDiagram (graph_diagram.hpp).
#include "grammar/pcg/graph_diagram.hpp"

#include "grammar/pcg/graph_order.hpp"

namespace shapevo::pcg {

void numberDiagram(GraphDiagram& diagram) {
    std::vector<OrderEdge> edges;
    edges.reserve(diagram.edges.size());
    for (const DiagramEdge& e : diagram.edges) edges.push_back({e.from, e.to, e.fromPort, e.toPort});
    const GraphOrder order = graphOrder(diagram.nodes.size(), edges);
    for (std::size_t i = 0; i < diagram.edges.size(); ++i) diagram.edges[i].cyclic = order.cyclic[i] != 0;
    for (std::size_t v = 0; v < diagram.nodes.size(); ++v) {
        diagram.nodes[v].order = order.order[v];
        diagram.nodes[v].loop = order.loop[v] != 0;
    }
}

DiagramCounts countDiagram(const GraphDiagram& diagram) {
    DiagramCounts c;
    c.nodes = diagram.nodes.size();
    c.edges = diagram.edges.size();
    for (const DiagramEdge& e : diagram.edges) c.cyclicEdges += e.cyclic;
    for (const DiagramNode& n : diagram.nodes) c.loopNodes += n.loop;
    return c;
}

}  // namespace shapevo::pcg
