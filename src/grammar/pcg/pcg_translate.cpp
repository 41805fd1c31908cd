// translatePcg and pcgDiagram (pcg_front_end.hpp). How a graph maps (grammars/pcg/README.md has
// the user's view):
//  - the graph is one rule (named after `graph NAME`) whose gene holds every `param`; its input
//    gates receive the start scope;
//  - every node is the shapevo statements of its op (pcg_nodes.cpp), written where the entity
//    arrives: an edge into a node that has one incoming edge is an inline successor;
//  - several edges out of one port (divergence) are `[ ]` blocks, one per edge (push / pop);
//  - several edges into a node (convergence) call one inline rule `pcg_n_ID` from each producer
//    (its arguments: the graph's values, so it computes what the graph rule would);
//  - a cyclic edge (§3.5) is a child slot `child pcg_c_ID optional`: a gene boundary, one gene per
//    step of the recursion, whose rule declares the graph's params again (each step evolves its
//    own values) and runs the node; the `if` node on the cycle ends it;
//  - a `chance(p)` node is a child slot `child pcg_y_ID prob p`: what follows it runs in a gene of
//    its own, expressed with probability p (the stochastic way out of a cycle, and what ends the
//    genome: an `if` ends the geometry, but a recursion that only an `if` ends still has genes);
//  - an unconnected output is a leaf: nothing follows (what the nodes on the way emitted stays);
//    a blocked output is `nil` (or left out of a comp);
//  - an edge into a collective node (a chain's first) is `send pcg_l_ID`; each chain of collective
//    nodes (pcg_collective.cpp) is a `gather pcg_l_ID { STEPS ROUTE }` at the end of its execution
//    scope's rule: the graph's rule, or for an included graph with collective nodes a rule
//    `pcg_s_GATE(values)` named as a statement where an entity reaches its input gate, so it runs
//    to completion (its gathers included) once per entity. A chain ending in a step routes `each`.
#include <algorithm>
#include <deque>
#include <filesystem>
#include <set>

#include "base/input_error.hpp"
#include "grammar/pcg/pcg_front_end.hpp"
#include "grammar/pcg/pcg_graph.hpp"

namespace shapevo::pcg {

namespace translate_detail {

struct Lines {
    std::vector<std::string> text;
    std::vector<Location> origin;
    int depth = 0;
};

class Emitter {
public:
    explicit Emitter(const FlatGraph& g) : g_(g), incoming_(g.nodes.size(), 0), requested_(g.nodes.size(), 0) {
        for (const FlatEdge& e : g.edges) ++incoming_[e.to];
    }

    Translation run() {
        Lines& header = buffers_.emplace_back();
        cur_ = &header;
        line("start " + g_.name, g_.nameAt);
        for (const GraphAttr& a : g_.attrs) line("attr " + a.name + " = " + a.value, a.where);
        for (const GraphAttr& a : g_.carried) line("carry " + a.name + " = " + a.value, a.where);
        cur_ = &buffers_.emplace_back();
        line("rule " + g_.name + " {", g_.nameAt);
        declareValues();
        std::vector<std::uint32_t> gates;
        for (std::uint32_t v = 0; v < g_.nodes.size(); ++v)
            if (g_.nodes[v].mainInput) gates.push_back(v);
        for (std::uint32_t v : gates) {
            if (gates.size() > 1) line("[", g_.nodes[v].where);
            flowOut(v, 0);
            if (gates.size() > 1) line("]", g_.nodes[v].where);
        }
        writeGathers(0);
        line("}", g_.nameAt);
        while (!pending_.empty() || !geneQueue_.empty()) {
            if (!pending_.empty()) {
                const auto [v, kind] = pending_.front();
                pending_.pop_front();
                if (kind == kScopeRule) writeScopeRule(v);
                else writeRule(v, kind == kChildRule);
            } else {
                const auto [v, port] = geneQueue_.front();
                geneQueue_.pop_front();
                writeGeneRule(v, port);
            }
        }
        Translation t;
        for (const Lines& b : buffers_) {
            for (const std::string& s : b.text) t.text += s + "\n";
            t.origin.insert(t.origin.end(), b.origin.begin(), b.origin.end());
        }
        t.files = g_.files;
        return t;
    }

    void line(const std::string& text, const Location& where) {
        if (!text.empty() && (text[0] == '}' || text[0] == ']')) --cur_->depth;
        cur_->text.push_back(std::string(std::size_t(2 * std::max(cur_->depth, 0)), ' ') + text);
        cur_->origin.push_back(where);
        if (!text.empty() && (text.back() == '{' || text.back() == '[')) ++cur_->depth;
    }

    bool flows(std::uint32_t v, std::size_t port) const {
        if (g_.nodes[v].outputs[port].blocked) return false;
        for (const FlatEdge& e : g_.edges)
            if (e.from == v && e.fromPort == port) return true;
        return false;
    }

    /// What follows output `port` of node `v`.
    void flowOut(std::uint32_t v, std::size_t port) {
        if (!flows(v, port)) return;
        std::vector<std::size_t> out;
        for (std::size_t i = 0; i < g_.edges.size(); ++i)
            if (g_.edges[i].from == v && g_.edges[i].fromPort == port) out.push_back(i);
        for (std::size_t i : out) {
            if (out.size() > 1) line("[", g_.edges[i].where);
            into(i);
            if (out.size() > 1) line("]", g_.edges[i].where);
        }
    }

private:
    class Writer final : public NodeWriter {
    public:
        Writer(Emitter& e, std::uint32_t v) : e_(e), n_(e.g_.nodes[v]), v_(v) {}
        const std::string& arg(std::size_t k) const override { return n_.args[k]; }
        const std::vector<std::string>& sizes() const override { return n_.sizes; }
        void line(const std::string& text) override { e_.line(text, n_.where); }
        bool flows(std::size_t port) const override { return e_.flows(v_, port); }
        void flow(std::size_t port) override { e_.flowOut(v_, port); }
        std::string childRule(std::size_t port) override { return e_.geneRule(v_, port); }
        [[noreturn]] void fail(const std::string& message) const override {
            throw InputError(n_.where.file, std::to_string(n_.where.line) + ":" + std::to_string(n_.where.column), message);
        }

    private:
        Emitter& e_;
        const FlatNode& n_;
        std::uint32_t v_;
    };

    /// The entity passing edge `i` reaches its node.
    void into(std::size_t i) {
        const FlatEdge& e = g_.edges[i];
        const FlatNode& n = g_.nodes[e.to];
        if (n.chain >= 0) {  // a collective input: the list's first node (the checks allow no other)
            line("send " + g_.chains[std::size_t(n.chain)].list, e.where);
        } else if (e.cyclic) {
            line("child pcg_c_" + n.ident + " optional", e.where);
            request(e.to, true);
        } else if (incoming_[e.to] > 1) {
            line("pcg_n_" + n.ident + valueList(), e.where);
            request(e.to, false);
        } else {
            node(e.to);
        }
    }

    void node(std::uint32_t v) {
        const FlatNode& n = g_.nodes[v];
        if (!n.op) {
            if (!n.includeName.empty() && !g_.scopes[n.scope].chains.empty()) {
                line("pcg_s_" + n.ident + valueList(), n.where);  // a run of the included graph, to completion
                request(v, kScopeRule);
                return;
            }
            flowOut(v, 0);  // a gate passes its entity on
            return;
        }
        Writer w(*this, v);
        n.op->write(w);
    }

    static constexpr std::uint8_t kInlineRule = 1, kChildRule = 2, kScopeRule = 4;

    void request(std::uint32_t v, bool child) { request(v, child ? kChildRule : kInlineRule); }
    void request(std::uint32_t v, std::uint8_t kind) {
        if (requested_[v] & kind) return;
        requested_[v] |= kind;
        pending_.push_back({v, kind});
    }

    /// The rule running an included graph's instance from its input gate `v`, its gathers last.
    void writeScopeRule(std::uint32_t v) {
        const FlatNode& n = g_.nodes[v];
        cur_ = &buffers_.emplace_back();
        line("rule pcg_s_" + n.ident + valueList() + " {", n.where);
        flowOut(v, 0);
        writeGathers(n.scope);
        line("}", n.where);
    }

    /// Every gather of execution scope `scope`, in the order the checks chose.
    void writeGathers(std::uint32_t scope) {
        for (std::uint32_t c : g_.scopes[scope].chains) {
            const ListChain& chain = g_.chains[c];
            const FlatNode& first = g_.nodes[chain.nodes.front()];
            line("gather " + chain.list + " {", first.where);
            for (std::uint32_t v : chain.nodes) {
                Writer w(*this, v);
                g_.nodes[v].op->write(w);  // a step's line, or a route
            }
            const std::uint32_t last = chain.nodes.back();
            if (g_.nodes[last].op->collect == Collect::Step) {
                if (!flows(last, 0)) {
                    line("each : nil", g_.nodes[last].where);
                } else {
                    line("each : {", g_.nodes[last].where);
                    flowOut(last, 0);
                    line("}", g_.nodes[last].where);
                }
            }
            line("}", first.where);
        }
    }

    /// A rule of its own gene running what follows output `port` of node `v` (a chance node's).
    std::string geneRule(std::uint32_t v, std::size_t port) {
        const std::string name = "pcg_y_" + g_.nodes[v].ident + (port ? "_" + std::to_string(port) : "");
        if (geneRules_.insert({v, port}).second) geneQueue_.push_back({v, port});
        return name;
    }

    void writeGeneRule(std::uint32_t v, std::size_t port) {
        const FlatNode& n = g_.nodes[v];
        cur_ = &buffers_.emplace_back();
        line("rule pcg_y_" + n.ident + (port ? "_" + std::to_string(port) : "") + " {", n.where);
        declareValues();
        flowOut(v, port);
        line("}", n.where);
    }

    void writeRule(std::uint32_t v, bool child) {
        const FlatNode& n = g_.nodes[v];
        cur_ = &buffers_.emplace_back();
        if (child) {
            line("rule pcg_c_" + n.ident + " {", n.where);
            declareValues();
            if (incoming_[v] > 1) {
                line("pcg_n_" + n.ident + valueList(), n.where);
                request(v, false);
            } else {
                node(v);
            }
        } else {
            line("rule pcg_n_" + n.ident + valueList() + " {", n.where);
            node(v);
        }
        line("}", n.where);
    }

    void declareValues() {
        for (const GraphValue& value : g_.values) line(value.declaration, value.where);
    }

    std::string valueList() const {
        if (g_.values.empty()) return "";
        std::string s = "(";
        for (std::size_t k = 0; k < g_.values.size(); ++k) s += (k ? ", " : "") + g_.values[k].name;
        return s + ")";
    }

    const FlatGraph& g_;
    std::vector<std::uint32_t> incoming_;
    std::vector<std::uint8_t> requested_;  ///< per node: kInlineRule, kChildRule, kScopeRule bits
    std::deque<std::pair<std::uint32_t, std::uint8_t>> pending_;  ///< a node and the rule kind to write for it
    std::set<std::pair<std::uint32_t, std::size_t>> geneRules_;
    std::deque<std::pair<std::uint32_t, std::size_t>> geneQueue_;
    std::deque<Lines> buffers_;
    Lines* cur_ = nullptr;
};

}  // namespace translate_detail

using namespace translate_detail;

Translation translatePcg(const std::string& text, const std::string& path) {
    const FlatGraph g = buildPcgGraph(text, path);
    return Emitter(g).run();
}

GraphDiagram pcgDiagram(const std::string& text, const std::string& path) {
    const FlatGraph g = buildPcgGraph(text, path);
    GraphDiagram d;
    d.title = std::filesystem::path(path).filename().string();
    for (const FlatNode& n : g.nodes) {
        DiagramNode node;
        node.name = n.name;
        node.detail = n.detail;
        node.start = n.mainInput;
        auto kind = [](const FlatPort& p) { return p.collective ? PortKind::Collective : PortKind::Single; };
        for (const FlatPort& p : n.inputs)
            if (!n.mainInput) node.ports.push_back({p.name, true, kind(p), false, p.gate});
        for (const FlatPort& p : n.outputs) node.ports.push_back({p.name, false, kind(p), p.blocked, p.gate});
        d.nodes.push_back(std::move(node));
    }
    for (const FlatEdge& e : g.edges) {
        const FlatNode& from = g.nodes[e.from];
        const std::size_t fromInputs = from.mainInput ? 0 : from.inputs.size();
        DiagramEdge edge;
        edge.from = e.from;
        edge.to = e.to;
        edge.fromPort = std::int32_t(fromInputs + e.fromPort);
        edge.toPort = std::int32_t(e.toPort);
        edge.blocked = from.outputs[e.fromPort].blocked;
        d.edges.push_back(edge);
    }
    numberDiagram(d);
    return d;
}

}  // namespace shapevo::pcg
