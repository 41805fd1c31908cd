// grammarDiagram (grammar_diagram.hpp): a Grammar's rules, slots and gathers as a GraphDiagram.
#include "grammar/grammar_diagram.hpp"

#include <filesystem>
#include <map>

#include "base/format_double.hpp"

namespace shapevo {

namespace {

std::string plural(std::size_t n, const std::string& word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

std::string ruleDetail(const Grammar& g, std::size_t id) {
    const Rule& r = g.rules[id];
    std::string d = id == g.start ? "start rule; " : "";
    std::size_t params = 0;
    for (const Param& p : r.params) params += p.dims;
    d += plural(params, "parameter") + ", gene of " + std::to_string(r.geneWords()) + " words";
    return d;
}

std::string slotLabel(const Slot& slot, std::size_t k, std::size_t alternative) {
    std::string label = "slot " + std::to_string(k + 1) + " \u00b7 edge " + std::to_string(slot.edge);
    if (slot.probability < 1.0f) label += " \u00b7 p " + formatDouble(slot.probability);
    if (slot.maxCount > 1) label += " \u00b7 \u00d7" + std::to_string(slot.maxCount);
    if (slot.optional) label += " \u00b7 optional";
    if (slot.rules.size() > 1) {
        float total = 0;
        for (float w : slot.weights) total += w;
        label += " \u00b7 alternative " + std::to_string(alternative + 1) + " of " + std::to_string(slot.rules.size()) +
                 " (weight " + formatDouble(slot.weights[alternative] / total) + ")";
    }
    return label;
}

/// A gather's steps in words: "order by, keep first".
std::string gatherSteps(const Grammar& g, const Gather& gather) {
    std::string steps;
    for (std::uint32_t k = 0; k < gather.ops; ++k) {
        const ListOp& op = g.listOps[gather.firstOp + k];
        if ((op.kind == ListOpKind::OrderBy || op.kind == ListOpKind::GroupBy) && k > 0 &&
            g.listOps[gather.firstOp + k - 1].kind == op.kind)
            continue;  // a further key of the same sort or grouping
        const char* name = "";
        switch (op.kind) {
        case ListOpKind::OrderBy: name = "order by"; break;
        case ListOpKind::Reverse: name = "reverse"; break;
        case ListOpKind::Shuffle: name = "shuffle"; break;
        case ListOpKind::Aggregate: name = "let"; break;
        case ListOpKind::GroupBy: name = "group by"; break;
        case ListOpKind::Cluster: name = "cluster"; break;
        case ListOpKind::Unify: name = "unify"; break;
        case ListOpKind::Merge: name = "merge"; break;
        case ListOpKind::Ungroup: name = "ungroup"; break;
        case ListOpKind::RayCast: name = "raycast"; break;
        case ListOpKind::Facing: name = "facing"; break;
        case ListOpKind::KeepFirst: name = "keep first"; break;
        case ListOpKind::Each: name = "each"; break;
        case ListOpKind::Where: name = "where"; break;
        }
        steps += (steps.empty() ? "" : ", ") + std::string(name);
    }
    return steps;
}

/// One node per gather (a collective input, square), an edge from the rule that gathers and one
/// from every rule that sends to its list (list order: gathers in file order).
void addGathers(const Grammar& g, pcg::GraphDiagram& d) {
    std::vector<std::uint32_t> gatherNode(g.gathers.size());
    for (std::size_t id = 0; id < g.rules.size(); ++id)
        for (const Statement& st : g.rules[id].statements)
            if (st.kind == StatementKind::Gather) {
                const Gather& gather = g.gathers[st.slot];
                pcg::DiagramNode node;
                node.name = "gather " + g.listNames[gather.list];
                node.detail = gatherSteps(g, gather);
                node.ports.push_back({"list", true, pcg::PortKind::Collective});
                gatherNode[st.slot] = std::uint32_t(d.nodes.size());
                d.nodes.push_back(std::move(node));
                d.edges.push_back({std::uint32_t(id), gatherNode[st.slot], -1, -1, "at the end of each run", pcg::EdgeKind::Inline});
            }
    for (std::size_t id = 0; id < g.rules.size(); ++id) {
        std::vector<bool> sent(g.listNames.size(), false);
        for (const Statement& st : g.rules[id].statements)
            if (st.kind == StatementKind::Send && !sent[st.slot]) {
                sent[st.slot] = true;
                for (std::size_t k = 0; k < g.gathers.size(); ++k)
                    if (g.gathers[k].list == st.slot)
                        d.edges.push_back({std::uint32_t(id), gatherNode[k], -1, 0, "send " + g.listNames[st.slot], pcg::EdgeKind::Inline});
            }
    }
}

}  // namespace

pcg::GraphDiagram grammarDiagram(const Grammar& g) {
    pcg::GraphDiagram d;
    d.title = std::filesystem::path(g.path).filename().string();
    d.nodeNoun = "rules";
    std::map<std::string, std::uint32_t> byName;
    for (std::size_t id = 0; id < g.rules.size(); ++id) {
        const Rule& r = g.rules[id];
        pcg::DiagramNode node;
        node.name = r.name;
        node.detail = ruleDetail(g, id);
        node.start = id == g.start;
        node.ports.push_back({"in", true});
        for (std::size_t k = 0; k < r.slots.size(); ++k) node.ports.push_back({"slot " + std::to_string(k + 1), false});
        byName.emplace(r.name, std::uint32_t(id));
        d.nodes.push_back(std::move(node));
    }
    for (const InlineCall& c : g.inlineCalls) {
        if (byName.count(c.callee)) continue;
        pcg::DiagramNode node;
        node.name = c.callee;
        node.detail = "runs only inline (no gene of its own)";
        node.ports.push_back({"in", true});
        byName.emplace(c.callee, std::uint32_t(d.nodes.size()));
        d.nodes.push_back(std::move(node));
    }
    std::vector<std::vector<const InlineCall*>> callsOf(g.rules.size());
    for (const InlineCall& c : g.inlineCalls) callsOf[c.rule].push_back(&c);
    for (std::size_t id = 0; id < g.rules.size(); ++id) {
        const Rule& r = g.rules[id];
        for (std::size_t k = 0; k < r.slots.size(); ++k)
            for (std::size_t a = 0; a < r.slots[k].rules.size(); ++a)
                d.edges.push_back({std::uint32_t(id), r.slots[k].rules[a], std::int32_t(k + 1), 0, slotLabel(r.slots[k], k, a),
                                   pcg::EdgeKind::Child});
        for (const InlineCall* c : callsOf[id])
            d.edges.push_back({std::uint32_t(id), byName.at(c->callee), -1, 0, "inline", pcg::EdgeKind::Inline});
    }
    if (g.hasLists) addGathers(g, d);
    pcg::numberDiagram(d);
    return d;
}

}  // namespace shapevo
