// Drawing a GraphDiagram (report/diagram_dot.hpp, graphviz_render.hpp, diagram_writer.hpp): the
// DOT text shows PCGR's notation (round single / square collective ports, filled blocked ports,
// thick gates, dashed cyclic edges left out of the ranking, blue inline calls, numbers counted
// from 1 and loop stars); Graphviz's library turns it into an SVG and a PNG without printing
// anything; bad DOT is an exception carrying Graphviz's message, not stderr noise; an existing
// output is refused.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "report/diagram_dot.hpp"
#include "report/diagram_writer.hpp"
#include "report/graphviz_render.hpp"

namespace shapevo {
namespace diagram_writer_test_helpers {

/// Two nodes with every kind of port, a flow edge, a cyclic edge back, an inline and a blocked edge.
pcg::GraphDiagram everyMark() {
    pcg::GraphDiagram d;
    d.title = "marks.pcg";
    pcg::DiagramNode a;
    a.name = "Lot";
    a.start = true;
    a.ports = {{"in", true, pcg::PortKind::Single, false, true}, {"out", false, pcg::PortKind::Single, false, false}};
    pcg::DiagramNode b;
    b.name = "Order \"by\" area";
    b.detail = "collective";
    b.ports = {{"list", true, pcg::PortKind::Collective}, {"rest", false, pcg::PortKind::Single, true}};
    d.nodes = {a, b};
    d.edges = {{0, 1, 1, 0, "flow", pcg::EdgeKind::Flow},
               {1, 0, 1, 0, "back", pcg::EdgeKind::Flow},
               {0, 1, -1, 0, "inline", pcg::EdgeKind::Inline},
               {1, 1, 1, 0, "blocked", pcg::EdgeKind::Flow, true}};
    pcg::numberDiagram(d);
    return d;
}

std::string lineWith(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    if (at == std::string::npos) return "";
    const std::size_t begin = text.rfind('\n', at) + 1;
    return text.substr(begin, text.find('\n', at) - begin);
}

}  // namespace diagram_writer_test_helpers

using namespace diagram_writer_test_helpers;

TEST(DiagramDot, ShowsPortsEdgesNumbersAndStarsInPcgrNotation) {
    const std::string dot = diagramDot(everyMark());
    EXPECT_EQ(dot.rfind("digraph \"marks.pcg\" {", 0), 0u) << dot;
    const std::string lot = lineWith(dot, "  n0 [label=<"), order = lineWith(dot, "  n1 [label=<");
    EXPECT_NE(lot.find("<TD>1 Lot *</TD>"), std::string::npos) << lot;
    EXPECT_NE(order.find("<TD>2 Order &quot;by&quot; area *</TD>"), std::string::npos) << "escaped: " << order;
    EXPECT_NE(order.find("<FONT POINT-SIZE=\"9\">collective</FONT>"), std::string::npos) << order;
    EXPECT_NE(lot.find("TABLE BORDER=\"3\""), std::string::npos) << "the start node is bold";
    EXPECT_NE(order.find("TABLE BORDER=\"1\""), std::string::npos);
    EXPECT_NE(lot.find("PORT=\"p0\" BORDER=\"2\""), std::string::npos) << "a gate is framed thick: " << lot;
    EXPECT_NE(lot.find("PORT=\"p1\" BORDER=\"0\""), std::string::npos) << lot;
    EXPECT_NE(lot.find("&#9675;"), std::string::npos) << "a single port is round";
    EXPECT_NE(order.find("&#9633;<BR/><FONT POINT-SIZE=\"8\">list</FONT>"), std::string::npos)
        << "a collective port is square: " << order;
    EXPECT_NE(order.find("rest</FONT><BR/>&#9679;"), std::string::npos) << "a blocked port is filled: " << order;
    EXPECT_EQ(lot.find("in</FONT>"), std::string::npos) << "a lone 'in' is not named";
    EXPECT_EQ(lineWith(dot, "label=\"flow\"").find("dashed"), std::string::npos);
    EXPECT_EQ(lineWith(dot, "label=\"flow\"").rfind("  n0:p1:s -> n1:p0:n [", 0), 0u) << "port to port";
    EXPECT_NE(lineWith(dot, "label=\"back\"").find("style=dashed, constraint=false"), std::string::npos) << dot;
    EXPECT_NE(lineWith(dot, "label=\"inline\"").find("#1f5fbf"), std::string::npos);
    EXPECT_EQ(lineWith(dot, "label=\"inline\"").rfind("  n0 -> n1:p0:n", 0), 0u) << "an edge without a port leaves the node";
    EXPECT_NE(lineWith(dot, "label=\"blocked\"").find("arrowhead=tee"), std::string::npos);
    EXPECT_EQ(dot, diagramDot(everyMark())) << "the same diagram, the same text";
}

TEST(GraphvizRender, WritesSvgAndPngQuietly) {
    const std::string dot = diagramDot(everyMark());
    testing::internal::CaptureStderr();
    const std::string svg = renderWithGraphviz(dot, "svg");
    const std::string png = renderWithGraphviz(dot, "png");
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(said, "") << "Graphviz printed on success";
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_NE(svg.find("Lot"), std::string::npos);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(GraphvizRender, BadDotIsAnExceptionWithGraphvizsMessageNotStderr) {
    testing::internal::CaptureStderr();
    try {
        renderWithGraphviz("digraph { a -> ", "svg");
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("Graphviz could not read the graph"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("syntax error"), std::string::npos) << e.what();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_THROW(renderWithGraphviz("digraph { a -> b }", "no-such-format"), std::runtime_error);
    EXPECT_NE(renderWithGraphviz("digraph { a -> b }", "svg").find("<svg"), std::string::npos) << "usable after failures";
}

TEST(DiagramWriter, WritesEachFormatAndNeverOverAnExistingFile) {
    test::TempDir dir;
    for (const std::string_view format : kDiagramFormats) {
        const std::string path = dir.file("g." + std::string(format));
        writeDiagram(everyMark(), format, path);
        EXPECT_GT(std::filesystem::file_size(path), 0u) << path;
        const auto before = std::filesystem::file_size(path);
        EXPECT_THROW(writeDiagram(everyMark(), format, path), InputError) << path;
        EXPECT_EQ(std::filesystem::file_size(path), before);
    }
    EXPECT_EQ(test::readFile(dir.file("g.dot")), diagramDot(everyMark()));
    EXPECT_THROW(writeDiagram(everyMark(), "svg", dir.file("no-such-folder/g.svg")), InputError);
}

}  // namespace shapevo
