// breadthFirstOrder: the original exporter's z-order (host_graph.hpp states it): breadth-first
// layers from the oldest unvisited live vertex, each layer's vertices then their new edges, and
// the edges with no end last. Only ids and creation order decide it: one graph, one order.
#include <cstdint>
#include <vector>

#include "graph/host_graph.hpp"

namespace shapevo::graph {

std::vector<DrawItem> breadthFirstOrder(const HostGraph& g) {
    const auto& vertices = g.vertices();
    const auto& edges = g.edges();
    std::vector<DrawItem> order;
    order.reserve(g.elements());
    std::vector<std::uint8_t> seen(vertices.size(), 0), listed(edges.size(), 0);
    std::vector<ElementId> layer, next;
    for (ElementId start = 0; start < vertices.size(); ++start) {
        if (!vertices[start].alive || seen[start]) continue;
        seen[start] = 1;
        layer.assign(1, start);
        while (!layer.empty()) {
            for (const ElementId v : layer) order.push_back({true, v});
            next.clear();
            for (const ElementId v : layer)
                for (const ElementId e : vertices[v].edges) {
                    if (listed[e] || !edges[e].alive) continue;
                    listed[e] = 1;
                    order.push_back({false, e});
                    const ElementId far = edges[e].vertex1 == v ? edges[e].vertex2 : edges[e].vertex1;
                    if (far != kNoVertex && !seen[far]) {
                        seen[far] = 1;
                        next.push_back(far);
                    }
                }
            layer.swap(next);
        }
    }
    for (ElementId e = 0; e < edges.size(); ++e)
        if (edges[e].alive && !listed[e] && edges[e].vertex1 == kNoVertex && edges[e].vertex2 == kNoVertex)
            order.push_back({false, e});
    return order;
}

}  // namespace shapevo::graph
