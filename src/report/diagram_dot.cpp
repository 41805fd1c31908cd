// diagramDot (diagram_dot.hpp): a GraphDiagram as Graphviz DOT text.
#include "report/diagram_dot.hpp"

#include <sstream>

namespace shapevo {

namespace {

constexpr const char* kInlineColour = "#1f5fbf";
constexpr const char* kBlockedColour = "#909090";

/// `text` as a DOT string, quotes included (backslashes and quotes escaped, newlines as \n).
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') out += "\\n";
        else out += c;
    }
    return out + "\"";
}

std::string nodeId(std::size_t node) { return "n" + std::to_string(node); }
std::string portId(std::size_t node, std::int32_t port) {
    return port < 0 ? nodeId(node) : nodeId(node) + "p" + std::to_string(port);
}

void writePort(std::ostream& out, std::size_t node, std::size_t k, const pcg::DiagramPort& p) {
    const bool collective = p.kind == pcg::PortKind::Collective;
    out << "    " << portId(node, std::int32_t(k)) << " [shape=" << (collective ? "square" : "circle")
        << ", width=0.14, height=0.14, fixedsize=true, label=\"\", style=filled, fillcolor=" << (p.blocked ? "black" : "white")
        << ", penwidth=" << (p.gate ? 3 : 1) << ", tooltip="
        << quoted(std::string(p.input ? "input " : "output ") + p.name + (collective ? " (collective)" : " (single)") +
                  (p.blocked ? ", blocked" : "") + (p.gate ? ", gate" : ""))
        << "];\n";
}

void writeNode(std::ostream& out, std::size_t i, const pcg::DiagramNode& n) {
    out << "  subgraph cluster_" << nodeId(i) << " {\n"
        << "    style=rounded; color=\"#404040\"; penwidth=" << (n.start ? "2.5" : "1") << "; label=\"\"; margin=6;\n";
    out << "    " << nodeId(i) << " [shape=plaintext, margin=0.02, label="
        << quoted(diagramNodeTitle(n) + (n.detail.empty() ? "" : "\n" + n.detail)) << "];\n";
    for (std::size_t k = 0; k < n.ports.size(); ++k) {
        writePort(out, i, k, n.ports[k]);
        const std::string port = portId(i, std::int32_t(k)), body = nodeId(i);
        out << "    " << (n.ports[k].input ? port + " -> " + body : body + " -> " + port) << " [style=invis, weight=10];\n";
    }
    out << "  }\n";
}

void writeEdge(std::ostream& out, const pcg::DiagramEdge& e) {
    out << "  " << portId(e.from, e.fromPort) << " -> " << portId(e.to, e.toPort) << " [label=" << quoted(e.label);
    if (e.cyclic) out << ", style=dashed, constraint=false";
    if (e.kind == pcg::EdgeKind::Inline) out << ", color=\"" << kInlineColour << "\", fontcolor=\"" << kInlineColour << "\"";
    if (e.blocked) out << ", color=\"" << kBlockedColour << "\", arrowhead=tee";
    out << "];\n";
}

std::string legend(const pcg::GraphDiagram& d) {
    bool child = false, inlineCall = false, flow = false;
    for (const pcg::DiagramEdge& e : d.edges) {
        child |= e.kind == pcg::EdgeKind::Child;
        inlineCall |= e.kind == pcg::EdgeKind::Inline;
        flow |= e.kind == pcg::EdgeKind::Flow;
    }
    std::string text = d.title + "\nN: topological order (PCGR \u00a73.4); *: node on a loop; dashed: cyclic edge (\u00a73.5)";
    if (child) text += "; black: child slot (a gene boundary)";
    if (inlineCall) text += "; blue: inline rule call (same gene)";
    if (flow) text += "; ports: round single, square collective, filled blocked, thick gate";
    return text;
}

}  // namespace

std::string diagramNodeTitle(const pcg::DiagramNode& node) {
    return std::to_string(node.order + 1) + " " + node.name + (node.loop ? " *" : "");
}

std::string diagramDot(const pcg::GraphDiagram& d) {
    std::ostringstream out;
    out << "digraph " << quoted(d.title) << " {\n"
        << "  graph [rankdir=TB, newrank=true, nodesep=0.3, ranksep=0.45, fontname=\"Helvetica\", fontsize=10, labelloc=b, "
           "labeljust=l, label="
        << quoted(legend(d)) << "];\n"
        << "  node [fontname=\"Helvetica\", fontsize=11];\n"
        << "  edge [fontname=\"Helvetica\", fontsize=9, arrowsize=0.7];\n";
    for (std::size_t i = 0; i < d.nodes.size(); ++i) writeNode(out, i, d.nodes[i]);
    for (const pcg::DiagramEdge& e : d.edges) writeEdge(out, e);
    out << "}\n";
    return out.str();
}

}  // namespace shapevo
