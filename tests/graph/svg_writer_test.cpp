// Tests of graph::drawingSvg: the original exporter's document (header, viewBox from the
// vertices' box, y negated, numbers as Python's repr, attributes sorted, <defs /> or the
// preamble's filters), rect and image geometry, escaping, the same bytes twice, and — on the
// original's Koch flake file, read from ../shared/ where present — the element counts of the
// original's own SVG.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "graph/derive.hpp"
#include "graph/drawing.hpp"
#include "graph/read_graph_grammar.hpp"
#include "graph/svg_writer.hpp"

namespace svg_writer_test {

using namespace shapevo::graph;

constexpr const char* kHeader = "<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n<svg baseProfile=\"full\" ";
constexpr const char* kNamespaces =
    "xmlns=\"http://www.w3.org/2000/svg\" xmlns:ev=\"http://www.w3.org/2001/xml-events\" "
    "xmlns:xlink=\"http://www.w3.org/1999/xlink\">";

/// One drawing made by hand (the writer reads nothing else).
Shape shape(ShapeKind kind, Vec2 centre, std::vector<DrawAttribute> attributes = {}) {
    Shape s;
    s.kind = kind;
    s.centre = centre;
    s.attributes = std::move(attributes);
    return s;
}

Drawing box(Vec2 min, Vec2 max) {
    Drawing d;
    d.hasVertices = true;
    d.min = min;
    d.max = max;
    return d;
}

TEST(GraphSvgWriter, WritesTheOriginalsDocument) {
    Drawing d = box({0, 0}, {1, 2});
    d.shapes.push_back(shape(ShapeKind::Circle, {0, 0}, {{"fill", "none"}, {"r", "0.4cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}}));
    Shape line = shape(ShapeKind::Line, {});
    line.end1 = {0, 0};
    line.end2 = {1, 2};
    line.attributes = {{"stroke", "black"}, {"stroke-width", "1mm"}};
    d.shapes.push_back(line);
    const std::string svg = drawingSvg(d, {}, canvasOf(d, 0));
    EXPECT_EQ(svg, std::string(kHeader) +
                       "height=\"70.86614\" preserveAspectRatio=\"xMidYMid meet\" version=\"1.1\" "
                       "viewBox=\"0.0 -70.86614 35.43307 70.86614\" width=\"35.43307\" " +
                       kNamespaces +
                       "<defs /><circle cx=\"0.0\" cy=\"-0.0\" fill=\"none\" r=\"0.4cm\" stroke=\"black\" stroke-width=\"1mm\" />"
                       "<line stroke=\"black\" stroke-width=\"1mm\" x1=\"0.0\" x2=\"35.43307\" y1=\"-0.0\" y2=\"-70.86614\" />"
                       "</svg>");
}

TEST(GraphSvgWriter, RectAndImageGeometryInUserUnits) {
    Drawing d = box({0, 0}, {0, 0});
    Shape rect = shape(ShapeKind::Rect, {1, 1}, {{"fill", "red"}});
    rect.width = 0.5;
    rect.height = 2;
    d.shapes.push_back(rect);
    Shape image = shape(ShapeKind::Image, {0, 0}, {{"xlink:href", "a.png"}});
    image.width = image.height = 1;
    image.rotation = 45;
    d.shapes.push_back(image);
    const std::string svg = drawingSvg(d, {}, canvasOf(d, 0));
    const double k = kUserUnitsPerModelUnit;
    std::ostringstream rectText;
    EXPECT_NE(svg.find("<rect fill=\"red\" height=\"70.86614\" width=\"17.716535\" x=\"" + toText(Value((1 - 0.25) * k)) +
                       "\" y=\"" + toText(Value(-((1 + 1.0) * k))) + "\" />"),
              std::string::npos)
        << svg;
    EXPECT_NE(svg.find("<image height=\"35.43307\" transform=\"rotate(45.0,0.0,-0.0)\" width=\"35.43307\" x=\"-17.716535\" "
                       "xlink:href=\"a.png\" y=\"-17.716535\" />"),
              std::string::npos)
        << svg;
}

TEST(GraphSvgWriter, FiltersGoIntoDefs) {
    SvgFilter f;
    f.id = "soft";
    f.primitives.push_back({"feGaussianBlur", {{"in_", "SourceGraphic"}, {"stdDeviation", "2"}}});
    f.primitives.push_back({"feColorMatrix", {{"color_interpolation_filters", "sRGB"}, {"onload", "x"}}});
    const Drawing d = box({0, 0}, {0, 0});
    const std::vector<SvgFilter> filters{f};
    const std::string svg = drawingSvg(d, filters, canvasOf(d, 0));
    EXPECT_NE(svg.find("<defs><filter id=\"soft\"><feGaussianBlur in=\"SourceGraphic\" stdDeviation=\"2\" />"
                       "<feColorMatrix color-interpolation-filters=\"sRGB\" /></filter></defs>"),
              std::string::npos)
        << svg;
}

TEST(GraphSvgWriter, EscapesEveryValue) {
    Drawing d = box({0, 0}, {0, 0});
    d.shapes.push_back(shape(ShapeKind::Path, {}, {{"d", "M 0 0"}, {"fill", "\"><script>&\n"}}));
    const std::string svg = drawingSvg(d, {}, canvasOf(d, 0));
    EXPECT_NE(svg.find("fill=\"&quot;&gt;&lt;script&gt;&amp;&#10;\""), std::string::npos) << svg;
    EXPECT_EQ(svg.find("<script"), std::string::npos);
}

TEST(GraphSvgWriter, MarginWidensTheViewBox) {
    const Drawing d = box({0, 0}, {2, 1});
    const std::string svg = drawingSvg(d, {}, canvasOf(d, 0.5));
    EXPECT_NE(svg.find("viewBox=\"-17.716535 -53.149605 106.29921 70.86614\""), std::string::npos) << svg;
}

/// The file's text, or "" if it cannot be read.
std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(GraphSvgWriter, KochFlakeDrawsWhatTheOriginalDrewAndTheSameBytesTwice) {
    const std::string shared = std::string(SHAPEVO_SOURCE_DIR) + "/../shared/graph-grammar/";
    const std::string file = shared + "original-examples/koch_flake.yml";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "the original's examples are not here: " << file;
    const GraphGrammar g = readGraphGrammar(file);
    auto svgOf = [&](std::uint64_t seed) {
        SeededDraws draws(seed);
        DeriveLimits limits;
        limits.maxSteps = 192;
        const DeriveResult r = deriveGraph(g, 0, draws, limits);
        const Drawing d = drawingOf(r.graph, g.names, g.path);
        return drawingSvg(d, g.filters, canvasOf(d, 0));
    };
    const std::string mine = svgOf(1);
    EXPECT_EQ(mine, svgOf(1));
    const std::string original = readText(shared + "reference-output/koch_flake_s1.svg");
    ASSERT_FALSE(original.empty());
    for (const char* tag : {"<circle ", "<line ", "<rect ", "<path "})
        EXPECT_EQ(occurrences(mine, tag), occurrences(original, tag)) << tag;
    // The flake's box does not depend on the random order of its steps.
    const auto header = [](const std::string& svg) { return svg.substr(0, svg.find("<defs")); };
    EXPECT_EQ(header(mine), header(original));
}

}  // namespace svg_writer_test
