// PCGR §3.4 / §3.5 graph order (graph_order.hpp): cyclic edges by the paper's depth-first search,
// topological numbers over the other edges, loop nodes by strongly connected components. Each
// search keeps an explicit stack, so a long chain of nodes cannot overflow the call stack.
#include "grammar/pcg/graph_order.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

namespace shapevo::pcg {

namespace {

constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();

/// Outgoing edges per node, each node's in edge order: edges out of node v are
/// list[first[v] .. first[v + 1]).
struct OutEdges {
    std::vector<std::uint32_t> first, list;
    OutEdges(std::size_t nodeCount, std::span<const OrderEdge> edges) : first(nodeCount + 1, 0), list(edges.size()) {
        for (const OrderEdge& e : edges) {
            if (e.from >= nodeCount || e.to >= nodeCount)
                throw std::out_of_range("graph order: an edge names node " + std::to_string(std::max(e.from, e.to)) + " of " +
                                        std::to_string(nodeCount));
            ++first[e.from + 1];
        }
        for (std::size_t v = 0; v < nodeCount; ++v) first[v + 1] += first[v];
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t i = 0; i < edges.size(); ++i) list[fill[edges[i].from]++] = i;  // stable: edge order kept
    }
    std::uint32_t begin(std::uint32_t v) const { return first[v]; }
    std::uint32_t end(std::uint32_t v) const { return first[v + 1]; }
};

struct Frame {
    std::uint32_t node;
    std::uint32_t next;  ///< position in OutEdges::list of the next edge to look at
};

}  // namespace

std::vector<std::uint8_t> findCyclicEdges(std::size_t nodeCount, std::span<const OrderEdge> edges) {
    const OutEdges out(nodeCount, edges);
    std::vector<std::uint8_t> visited(edges.size(), 0), cyclic(edges.size(), 0), onPath(nodeCount, 0);
    std::vector<Frame> path;
    for (std::uint32_t start = 0; start < nodeCount; ++start) {
        path.push_back({start, out.begin(start)});  // (2): a fresh list of visited nodes; (a) start joins it
        onPath[start] = 1;
        while (!path.empty()) {
            Frame& f = path.back();
            if (f.next == out.end(f.node)) {  // every outgoing edge looked at: back to the caller's list
                onPath[f.node] = 0;
                path.pop_back();
                continue;
            }
            const std::uint32_t e = out.list[f.next++];
            if (visited[e]) continue;  // (b) only "unvisited" edges, as marked by now
            const std::uint32_t to = edges[e].to;
            if (onPath[to]) {  // (i) the destination is in the list
                cyclic[e] = 1;
                continue;
            }
            visited[e] = 1;  // (ii) visited, and on at the destination with a copy of the list
            onPath[to] = 1;
            path.push_back({to, out.begin(to)});
        }
    }
    return cyclic;
}

std::vector<std::uint32_t> topologicalNumbers(std::size_t nodeCount, std::span<const OrderEdge> edges,
                                              std::span<const std::uint8_t> cyclic) {
    const OutEdges out(nodeCount, edges);
    std::vector<std::uint32_t> incoming(nodeCount, 0), order(nodeCount, kUnset);
    for (std::size_t i = 0; i < edges.size(); ++i)
        if (!cyclic[i]) ++incoming[edges[i].to];
    std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> ready;  // first in file order on top
    std::uint32_t next = 0;
    const auto number = [&](std::uint32_t v) {
        order[v] = next++;
        for (std::uint32_t k = out.begin(v); k < out.end(v); ++k) {
            const std::uint32_t e = out.list[k];
            if (!cyclic[e] && --incoming[edges[e].to] == 0) ready.push(edges[e].to);
        }
    };
    std::vector<std::uint32_t> sources;
    for (std::uint32_t v = 0; v < nodeCount; ++v)
        if (incoming[v] == 0) sources.push_back(v);
    for (const std::uint32_t v : sources) number(v);  // source nodes first, in file order
    while (!ready.empty()) {
        const std::uint32_t v = ready.top();
        ready.pop();
        number(v);
    }
    if (next != nodeCount) throw std::logic_error("graph order: the edges not marked cyclic still form a cycle");
    return order;
}

std::vector<std::uint8_t> loopNodes(std::size_t nodeCount, std::span<const OrderEdge> edges) {
    // Tarjan's strongly connected components, with an explicit stack.
    const OutEdges out(nodeCount, edges);
    std::vector<std::uint32_t> index(nodeCount, kUnset), low(nodeCount, 0), component;
    std::vector<std::uint8_t> onComponentStack(nodeCount, 0), loop(nodeCount, 0);
    std::vector<Frame> calls;
    std::uint32_t counter = 0;
    const auto enter = [&](std::uint32_t v) {
        index[v] = low[v] = counter++;
        component.push_back(v);
        onComponentStack[v] = 1;
        calls.push_back({v, out.begin(v)});
    };
    for (std::uint32_t s = 0; s < nodeCount; ++s) {
        if (index[s] != kUnset) continue;
        enter(s);
        while (!calls.empty()) {
            const std::uint32_t v = calls.back().node;
            if (calls.back().next < out.end(v)) {
                const std::uint32_t w = edges[out.list[calls.back().next++]].to;
                if (w == v) loop[v] = 1;  // a self-loop
                if (index[w] == kUnset) enter(w);
                else if (onComponentStack[w]) low[v] = std::min(low[v], index[w]);
                continue;
            }
            calls.pop_back();
            if (!calls.empty()) low[calls.back().node] = std::min(low[calls.back().node], low[v]);
            if (low[v] != index[v]) continue;
            std::size_t root = component.size() - 1;  // v and the nodes above it on the stack form its component
            while (component[root] != v) --root;
            const bool cycle = component.size() - root > 1;
            for (std::size_t k = root; k < component.size(); ++k) {
                onComponentStack[component[k]] = 0;
                if (cycle) loop[component[k]] = 1;
            }
            component.resize(root);
        }
    }
    return loop;
}

GraphOrder graphOrder(std::size_t nodeCount, std::span<const OrderEdge> edges) {
    GraphOrder g;
    g.cyclic = findCyclicEdges(nodeCount, edges);
    g.order = topologicalNumbers(nodeCount, edges, g.cyclic);
    g.loop = loopNodes(nodeCount, edges);
    return g;
}

}  // namespace shapevo::pcg
