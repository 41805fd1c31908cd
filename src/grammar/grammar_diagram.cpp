// grammarDiagram (grammar_diagram.hpp): a Grammar's rules and slots as a GraphDiagram.
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
    pcg::numberDiagram(d);
    return d;
}

}  // namespace shapevo
