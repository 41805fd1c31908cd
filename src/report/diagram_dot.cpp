// diagramDot (diagram_dot.hpp): a GraphDiagram as Graphviz DOT text, each node an HTML-like table.
#include "report/diagram_dot.hpp"

#include <sstream>

#include "report/svg_painter.hpp"  // xmlEscape: HTML-like labels escape as XML does

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

/// A port's glyph: round single, square collective; filled when blocked.
const char* portGlyph(const pcg::DiagramPort& p) {
    if (p.kind == pcg::PortKind::Collective) return p.blocked ? "&#9632;" : "&#9633;";
    return p.blocked ? "&#9679;" : "&#9675;";
}

/// The row of `node`'s input (or output) ports, or "" if it has none: a cell per port, its glyph
/// (framed thick for a gate) and, unless it is the side's only port and is called in / out, its name.
std::string portRow(const pcg::DiagramNode& node, bool inputs) {
    std::size_t count = 0;
    for (const pcg::DiagramPort& p : node.ports) count += p.input == inputs;
    if (count == 0) return "";
    std::string row = "<TR><TD><TABLE BORDER=\"0\" CELLSPACING=\"2\" CELLPADDING=\"1\"><TR>";
    for (std::size_t k = 0; k < node.ports.size(); ++k) {
        const pcg::DiagramPort& p = node.ports[k];
        if (p.input != inputs) continue;
        const bool named = !(count == 1 && p.name == (inputs ? "in" : "out"));
        const std::string tooltip = std::string(inputs ? "input " : "output ") + p.name +
                                    (p.kind == pcg::PortKind::Collective ? " (collective)" : " (single)") +
                                    (p.blocked ? ", blocked" : "") + (p.gate ? ", gate" : "");
        row += "<TD PORT=\"p" + std::to_string(k) + "\" BORDER=\"" + (p.gate ? "2" : "0") + "\" TOOLTIP=\"" + xmlEscape(tooltip) +
               "\">";
        const std::string name = named ? "<FONT POINT-SIZE=\"8\">" + xmlEscape(p.name) + "</FONT>" : "";
        row += inputs ? portGlyph(p) + (named ? "<BR/>" + name : "") : (named ? name + "<BR/>" : "") + portGlyph(p);
        row += "</TD>";
    }
    return row + "</TR></TABLE></TD></TR>";
}

void writeNode(std::ostream& out, std::size_t i, const pcg::DiagramNode& n) {
    out << "  " << nodeId(i) << " [label=<<TABLE BORDER=\"" << (n.start ? 3 : 1)
        << "\" CELLBORDER=\"0\" CELLSPACING=\"0\" CELLPADDING=\"2\" STYLE=\"rounded\">" << portRow(n, true) << "<TR><TD>"
        << xmlEscape(diagramNodeTitle(n)) << "</TD></TR>";
    if (!n.detail.empty()) out << "<TR><TD><FONT POINT-SIZE=\"9\">" << xmlEscape(n.detail) << "</FONT></TD></TR>";
    out << portRow(n, false) << "</TABLE>>];\n";
}

std::string endpoint(std::uint32_t node, std::int32_t port, const char* side) {
    return port < 0 ? nodeId(node) : nodeId(node) + ":p" + std::to_string(port) + ":" + side;
}

void writeEdge(std::ostream& out, const pcg::DiagramEdge& e) {
    out << "  " << endpoint(e.from, e.fromPort, "s") << " -> " << endpoint(e.to, e.toPort, "n") << " [label=" << quoted(e.label);
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
    if (flow) text += "\nports: \u25cb single, \u25a1 collective, filled: blocked, framed: gate";
    return text;
}

}  // namespace

std::string diagramNodeTitle(const pcg::DiagramNode& node) {
    return std::to_string(node.order + 1) + " " + node.name + (node.loop ? " *" : "");
}

std::string diagramDot(const pcg::GraphDiagram& d) {
    std::ostringstream out;
    out << "digraph " << quoted(d.title) << " {\n"
        << "  graph [rankdir=TB, nodesep=0.35, ranksep=0.5, fontname=\"Helvetica\", fontsize=10, labelloc=b, labeljust=l, "
           "label="
        << quoted(legend(d)) << "];\n"
        << "  node [shape=plain, fontname=\"Helvetica\", fontsize=11];\n"
        << "  edge [fontname=\"Helvetica\", fontsize=9, arrowsize=0.7];\n";
    for (std::size_t i = 0; i < d.nodes.size(); ++i) writeNode(out, i, d.nodes[i]);
    for (const pcg::DiagramEdge& e : d.edges) writeEdge(out, e);
    out << "}\n";
    return out.str();
}

}  // namespace shapevo
