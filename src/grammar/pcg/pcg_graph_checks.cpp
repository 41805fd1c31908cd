// checkPcgGraph (pcg_graph.hpp): the checks that need the whole expanded graph — connected inputs,
// cyclic edges, reachability, port types and the ways out of cycles.
#include <algorithm>
#include <deque>

#include "base/input_error.hpp"
#include "grammar/pcg/graph_order.hpp"
#include "grammar/pcg/pcg_graph.hpp"

namespace shapevo::pcg {

namespace graph_checks_detail {

[[noreturn]] void failAt(const Location& l, const std::string& what) {
    throw InputError(l.file, std::to_string(l.line) + ":" + std::to_string(l.column), what);
}

std::string portName(const FlatNode& n, const FlatPort& p) { return n.gate ? n.name : n.name + "." + p.name; }

void checkInputsConnected(const FlatGraph& g) {
    std::vector<std::vector<std::uint8_t>> fed(g.nodes.size());
    for (std::size_t v = 0; v < g.nodes.size(); ++v) fed[v].assign(g.nodes[v].inputs.size(), 0);
    for (const FlatEdge& e : g.edges) fed[e.to][e.toPort] = 1;
    for (std::size_t v = 0; v < g.nodes.size(); ++v) {
        const FlatNode& n = g.nodes[v];
        for (std::size_t k = 0; k < n.inputs.size(); ++k) {
            if (fed[v][k] || n.mainInput) continue;
            if (n.op && n.inputs[k].collective)
                failAt(n.where, "collective input '" + n.inputs[k].name + "' of node '" + n.name + "' (" + n.op->name +
                                    ") is not connected: it gathers what edges send to it, and none does");
            if (n.op)
                failAt(n.where, "input '" + n.inputs[k].name + "' of node '" + n.name + "' (" + n.op->name +
                                    ") is not connected: an edge must lead to it");
            if (!n.includeName.empty())
                failAt(n.includeAt, "input '" + n.name.substr(n.name.rfind('/') + 1) + "' of node '" + n.includeName +
                                        "' (an included graph) is not connected: an edge must lead to it");
        }
    }
}

void checkReached(const FlatGraph& g) {
    std::vector<std::uint8_t> seen(g.nodes.size(), 0);
    std::deque<std::uint32_t> todo;
    for (std::uint32_t v = 0; v < g.nodes.size(); ++v)
        if (g.nodes[v].mainInput) seen[v] = 1, todo.push_back(v);
    std::vector<std::vector<std::uint32_t>> out(g.nodes.size());
    for (const FlatEdge& e : g.edges) out[e.from].push_back(e.to);
    while (!todo.empty()) {
        const std::uint32_t v = todo.front();
        todo.pop_front();
        for (std::uint32_t w : out[v])
            if (!seen[w]) seen[w] = 1, todo.push_back(w);
    }
    for (std::size_t v = 0; v < g.nodes.size(); ++v)
        if (!seen[v] && g.nodes[v].op)
            failAt(g.nodes[v].where, "node '" + g.nodes[v].name + "' is never reached: no path leads to it from an input gate");
}

void resolveTypes(FlatGraph& g, const std::vector<OrderEdge>& edges) {
    std::vector<std::uint8_t> cyclic(g.edges.size());
    for (std::size_t i = 0; i < g.edges.size(); ++i) cyclic[i] = g.edges[i].cyclic;
    const std::vector<std::uint32_t> order = topologicalNumbers(g.nodes.size(), edges, cyclic);
    std::vector<std::uint32_t> byOrder(g.nodes.size());
    for (std::uint32_t v = 0; v < g.nodes.size(); ++v) byOrder[order[v]] = v;
    std::vector<std::vector<std::size_t>> incoming(g.nodes.size());
    for (std::size_t i = 0; i < g.edges.size(); ++i)
        if (!g.edges[i].cyclic) incoming[g.edges[i].to].push_back(i);
    for (std::uint32_t v : byOrder) {
        bool any = false;
        PortType in = PortType::Entity;
        for (std::size_t i : incoming[v]) {
            const FlatEdge& e = g.edges[i];
            const PortType t = g.nodes[e.from].outputs[e.fromPort].type;
            in = !any || t == in ? t : PortType::Entity;
            any = true;
        }
        for (FlatPort& p : g.nodes[v].outputs)
            if (p.type == PortType::Same) p.type = in;
    }
    for (const FlatEdge& e : g.edges) {
        const FlatNode& from = g.nodes[e.from];
        const FlatNode& to = g.nodes[e.to];
        const FlatPort& out = from.outputs[e.fromPort];
        const FlatPort& in = to.inputs[e.toPort];
        if (in.type == PortType::Entity || in.type == out.type) continue;
        const std::string takes = to.op ? std::string(to.op->name) + " takes " : "the gate takes ";
        failAt(e.where, "cannot connect " + portName(from, out) + " (" + portTypeName(out.type) + ") to " + portName(to, in) + " (" +
                            portTypeName(in.type) + "): " + takes + (in.type == PortType::Volume ? "a volume" : "a flat scope") +
                            (out.type == PortType::Entity ? ", and this port may carry either" : ""));
    }
}

void checkWaysOut(const FlatGraph& g) {
    std::vector<std::vector<std::uint32_t>> out(g.nodes.size()), in(g.nodes.size());
    for (const FlatEdge& e : g.edges) out[e.from].push_back(e.to), in[e.to].push_back(e.from);
    auto reach = [&](std::uint32_t start, const std::vector<std::vector<std::uint32_t>>& next) {
        std::vector<std::uint8_t> seen(g.nodes.size(), 0);
        std::vector<std::uint32_t> todo{start};
        seen[start] = 1;
        while (!todo.empty()) {
            const std::uint32_t v = todo.back();
            todo.pop_back();
            for (std::uint32_t w : next[v])
                if (!seen[w]) seen[w] = 1, todo.push_back(w);
        }
        return seen;
    };
    for (const FlatEdge& e : g.edges) {
        if (!e.cyclic) continue;
        const std::vector<std::uint8_t> ahead = reach(e.to, out), behind = reach(e.from, in);
        std::string names;
        bool wayOut = false;
        for (std::size_t v = 0; v < g.nodes.size(); ++v) {
            if (!ahead[v] || !behind[v]) continue;
            names += (names.empty() ? "" : ", ") + g.nodes[v].name;
            wayOut = wayOut || (g.nodes[v].op && g.nodes[v].op->wayOut);
        }
        if (!wayOut)
            failAt(e.where, "a cycle with no way out (through " + names +
                                "): it would never end; put an `if` or a `chance` node on it");
    }
}

}  // namespace graph_checks_detail

using namespace graph_checks_detail;

void checkPcgGraph(FlatGraph& g) {
    checkInputsConnected(g);
    std::vector<OrderEdge> edges;
    edges.reserve(g.edges.size());
    for (const FlatEdge& e : g.edges) edges.push_back({e.from, e.to, std::int32_t(e.fromPort), std::int32_t(e.toPort)});
    const std::vector<std::uint8_t> cyclic = findCyclicEdges(g.nodes.size(), edges);
    for (std::size_t i = 0; i < g.edges.size(); ++i) g.edges[i].cyclic = cyclic[i] != 0;
    checkReached(g);
    resolveTypes(g, edges);
    checkWaysOut(g);
    checkCollectiveNodes(g);
}

}  // namespace shapevo::pcg
