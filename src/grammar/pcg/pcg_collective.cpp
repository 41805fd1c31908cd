// checkCollectiveNodes (pcg_graph.hpp): the collective nodes of a `.pcg` graph (PCGR's square
// ports) grouped into gathers, and the checks that keep each list inside its execution scope and
// its gene, so that the translation's `send` always finds its `gather`:
//  - a chain: a collective node fed by exactly one edge, from the `out` of a step node (order_by,
//    reverse, shuffle) that has no other edge, continues that node's gather; any other collective
//    node starts a gather of its own, named pcg_l_IDENT, in the scope the node belongs to (the main
//    graph's rule, or the rule that runs an included graph once per entity reaching its gate);
//  - a list never passes a gate straight into another scope's collective node;
//  - no send comes from another gene: nothing after a cyclic edge or a chance node feeds a
//    collective node of a scope whose invocation started before that boundary;
//  - within a scope, a gather whose routes send into another gather runs before it; lists that
//    feed each other round a circle are refused.
#include <algorithm>
#include <deque>

#include "base/input_error.hpp"
#include "grammar/pcg/pcg_graph.hpp"

namespace shapevo::pcg {

namespace collective_detail {

[[noreturn]] void failAt(const Location& l, const std::string& what) {
    throw InputError(l.file, std::to_string(l.line) + ":" + std::to_string(l.column), what);
}

std::string named(const FlatNode& n) { return "'" + n.name + "' (" + (n.op ? n.op->name : "gate") + ")"; }

bool collectiveNode(const FlatNode& n) { return n.op && n.op->collect != Collect::None; }

/// The edges leaving each node and entering each node, by index.
struct Adjacency {
    std::vector<std::vector<std::size_t>> out, in;
    explicit Adjacency(const FlatGraph& g) : out(g.nodes.size()), in(g.nodes.size()) {
        for (std::size_t i = 0; i < g.edges.size(); ++i) out[g.edges[i].from].push_back(i), in[g.edges[i].to].push_back(i);
    }
};

/// The one edge that makes `v` the next node of a chain, or -1.
std::int64_t continuationEdge(const FlatGraph& g, const Adjacency& a, std::uint32_t v) {
    if (!collectiveNode(g.nodes[v]) || a.in[v].size() != 1) return -1;
    const FlatEdge& e = g.edges[a.in[v].front()];
    const FlatNode& u = g.nodes[e.from];
    if (e.cyclic || !u.op || u.op->collect != Collect::Step || u.outputs[e.fromPort].blocked) return -1;
    std::size_t leaving = 0;
    for (std::size_t i : a.out[e.from]) leaving += g.edges[i].fromPort == e.fromPort;
    return leaving == 1 ? std::int64_t(a.in[v].front()) : -1;
}

void buildChains(FlatGraph& g, const Adjacency& a) {
    for (std::uint32_t v = 0; v < g.nodes.size(); ++v) {
        if (!collectiveNode(g.nodes[v]) || continuationEdge(g, a, v) >= 0) continue;
        ListChain c;
        c.scope = g.nodes[v].scope;
        c.list = "pcg_l_" + g.nodes[v].ident;
        for (std::uint32_t w = v;;) {
            c.nodes.push_back(w);
            g.nodes[w].chain = std::int32_t(g.chains.size());
            if (g.nodes[w].op->collect != Collect::Step || a.out[w].size() != 1) break;
            const std::uint32_t next = g.edges[a.out[w].front()].to;
            if (continuationEdge(g, a, next) < 0) break;
            w = next;
        }
        g.scopes[c.scope].chains.push_back(std::uint32_t(g.chains.size()));
        g.chains.push_back(std::move(c));
    }
}

/// A list out of a collective port that goes through gates straight into a collective node.
void checkGates(const FlatGraph& g, const Adjacency& a) {
    for (const FlatEdge& e : g.edges) {
        const FlatNode& from = g.nodes[e.from];
        if (!from.outputs[e.fromPort].collective || !g.nodes[e.to].gate) continue;
        std::vector<std::uint32_t> todo{e.to};
        std::vector<std::uint8_t> seen(g.nodes.size(), 0);
        while (!todo.empty()) {
            const std::uint32_t v = todo.back();
            todo.pop_back();
            for (std::size_t i : a.out[v]) {
                const FlatNode& w = g.nodes[g.edges[i].to];
                if (collectiveNode(w))
                    failAt(e.where, "the list out of " + from.name + "." + from.outputs[e.fromPort].name + " would go through gate '" +
                                        g.nodes[e.to].name + "' into " + named(w) + " of another execution scope: a list stays in "
                                        "the graph that gathers it; let a node with single ports take its entities first");
                if (w.gate && !seen[g.edges[i].to]) seen[g.edges[i].to] = 1, todo.push_back(g.edges[i].to);
            }
        }
    }
}

bool entryOf(const FlatGraph& g, std::uint32_t v, std::uint32_t scope) {
    const FlatNode& n = g.nodes[v];
    return scope != 0 && n.gate && n.scope == scope && !n.includeName.empty();
}

/// No send into a gather of scope S comes from a gene that S's invocation did not start.
void checkGenes(const FlatGraph& g, const Adjacency& a, std::uint32_t scope) {
    // what each node runs after: the boundary (a cyclic edge or a chance node) that puts it in a new gene
    std::vector<std::string> after(g.nodes.size());
    std::deque<std::uint32_t> todo;
    auto seed = [&](std::uint32_t v, const std::string& boundary) {
        if (after[v].empty() && !entryOf(g, v, scope)) after[v] = boundary, todo.push_back(v);
    };
    for (const FlatEdge& e : g.edges) {
        const FlatNode& from = g.nodes[e.from];
        if (e.cyclic) seed(e.to, "the cyclic edge " + from.name + " -> " + g.nodes[e.to].name);
        else if (from.op && from.op->newGene) seed(e.to, "the chance node '" + from.name + "'");
    }
    while (!todo.empty()) {
        const std::uint32_t v = todo.front();
        todo.pop_front();
        for (std::size_t i : a.out[v]) seed(g.edges[i].to, after[v]);
    }
    for (std::uint32_t c : g.scopes[scope].chains) {
        const std::uint32_t head = g.chains[c].nodes.front();
        for (std::size_t i : a.in[head]) {
            const FlatEdge& e = g.edges[i];
            const FlatNode& from = g.nodes[e.from];
            std::string boundary = after[e.from];
            if (e.cyclic) boundary = "the cyclic edge " + from.name + " -> " + g.nodes[head].name;
            else if (from.op && from.op->newGene) boundary = "the chance node '" + from.name + "'";
            if (boundary.empty()) continue;
            failAt(e.where, "the edge from '" + from.name + "' sends to " + named(g.nodes[head]) + " from another gene (after " +
                                boundary + "), but " + named(g.nodes[head]) + " gathers in " +
                                (scope ? "each run of " + g.scopes[scope].name : "graph " + g.scopes[0].name) +
                                ": a list never crosses a gene boundary; put the collective nodes in a graph included after it");
        }
    }
}

/// Scope S's gathers in an order where a gather whose routes send into another runs first.
void orderGathers(FlatGraph& g, const Adjacency& a, std::uint32_t scope) {
    std::vector<std::uint32_t>& chains = g.scopes[scope].chains;
    const std::size_t n = chains.size();
    std::vector<std::vector<std::size_t>> feeds(n);  // k -> the chains (local index) it sends to
    std::vector<std::size_t> waiting(n, 0);
    std::vector<std::size_t> closing(n, 0);          // an edge into chain k's head from a route
    std::vector<std::int64_t> local(g.chains.size(), -1);
    for (std::size_t k = 0; k < n; ++k) local[chains[k]] = std::int64_t(k);
    for (std::size_t k = 0; k < n; ++k) {
        std::vector<std::uint8_t> seen(g.nodes.size(), 0);
        std::vector<std::uint32_t> todo{g.chains[chains[k]].nodes.back()};
        std::vector<std::uint8_t> fed(n, 0);
        while (!todo.empty()) {
            const std::uint32_t v = todo.back();
            todo.pop_back();
            for (std::size_t i : a.out[v]) {
                const std::uint32_t w = g.edges[i].to;
                const FlatNode& target = g.nodes[w];
                const std::int64_t j = target.chain >= 0 ? local[std::size_t(target.chain)] : -1;
                if (j >= 0 && g.chains[std::size_t(target.chain)].nodes.front() == w) {
                    if (std::size_t(j) == k)
                        failAt(g.edges[i].where, "what the gather of " + named(g.nodes[g.chains[chains[k]].nodes.back()]) +
                                                     " routes comes back into its own list at " + named(target) +
                                                     ": a list cannot feed itself; send it to another collective node");
                    if (!fed[std::size_t(j)]) fed[std::size_t(j)] = 1, feeds[k].push_back(std::size_t(j)), ++waiting[std::size_t(j)];
                    closing[std::size_t(j)] = i;
                    continue;
                }
                if (!seen[w] && !entryOf(g, w, scope)) seen[w] = 1, todo.push_back(w);
            }
        }
    }
    std::vector<std::uint32_t> ordered;
    std::vector<std::uint8_t> done(n, 0);
    while (ordered.size() < n) {
        std::size_t next = n;
        for (std::size_t k = 0; k < n && next == n; ++k)
            if (!done[k] && waiting[k] == 0) next = k;
        if (next == n) {
            std::size_t k = 0;
            while (done[k]) ++k;
            const FlatEdge& e = g.edges[closing[k]];
            failAt(e.where, "lists feed each other round a circle (the edge from '" + g.nodes[e.from].name + "' into " +
                                named(g.nodes[e.to]) + "): each gather would have to run after the other");
        }
        done[next] = 1;
        ordered.push_back(chains[next]);
        for (std::size_t j : feeds[next]) --waiting[j];
    }
    chains = std::move(ordered);
}

}  // namespace collective_detail

using namespace collective_detail;

void checkCollectiveNodes(FlatGraph& g) {
    if (std::none_of(g.nodes.begin(), g.nodes.end(), collectiveNode)) return;
    const Adjacency a(g);
    buildChains(g, a);
    checkGates(g, a);
    for (std::uint32_t s = 0; s < g.scopes.size(); ++s)
        if (!g.scopes[s].chains.empty()) checkGenes(g, a, s);
    for (std::uint32_t s = 0; s < g.scopes.size(); ++s)
        if (!g.scopes[s].chains.empty()) orderGathers(g, a, s);
}

}  // namespace shapevo::pcg
