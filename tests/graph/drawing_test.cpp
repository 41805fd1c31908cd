// Tests of graph::drawingOf and canvasOf (graph-grammar README, section 4): the default circle
// and line, the tags (rect, path, circle, image, line, None in its three spellings), `.svg_<name>`
// attributes overriding the defaults, filters, geometry kept from the element, dangling edges
// and helper vertices drawn as nothing, the vertices' box and the margin, and each refusal.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "base/input_error.hpp"
#include "graph/drawing.hpp"

namespace drawing_test {

using shapevo::InputError;
using namespace shapevo::graph;

/// A graph under construction with its attribute names.
struct Scene {
    AttrNames names;
    HostGraph graph;

    AttrMap attrs(std::vector<std::pair<std::string, Value>> list) {
        AttrMap m;
        for (auto& [k, v] : list) m.set(names.intern(k), std::move(v));
        return m;
    }
    ElementId vertex(double x, double y, std::vector<std::pair<std::string, Value>> list = {}) {
        return graph.addVertex(Vec2{x, y}, attrs(std::move(list)), 0);
    }
    ElementId edge(ElementId a, ElementId b, std::vector<std::pair<std::string, Value>> list = {}) {
        return graph.addEdge(a, b, attrs(std::move(list)), 0);
    }
    Drawing draw() const { return drawingOf(graph, names, "scene.yml"); }
};

std::vector<DrawAttribute> list(std::vector<std::pair<std::string, std::string>> pairs) {
    std::vector<DrawAttribute> out;
    for (auto& [n, v] : pairs) out.push_back({n, v});
    return out;
}

TEST(GraphDrawing, UntaggedVertexIsACircleAndEdgeALine) {
    Scene s;
    const ElementId a = s.vertex(1, 2);
    s.edge(a, s.vertex(3, -1));
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 3u);
    EXPECT_EQ(d.shapes[0].kind, ShapeKind::Circle);
    EXPECT_EQ(d.shapes[0].centre, (Vec2{1, 2}));
    EXPECT_EQ(d.shapes[0].attributes, list({{"fill", "none"}, {"r", "0.4cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}}));
    EXPECT_EQ(d.shapes[1].kind, ShapeKind::Line);
    EXPECT_FALSE(d.shapes[1].element.isVertex);
    EXPECT_EQ(d.shapes[1].end1, (Vec2{1, 2}));
    EXPECT_EQ(d.shapes[1].end2, (Vec2{3, -1}));
    EXPECT_EQ(d.shapes[1].attributes, list({{"stroke", "black"}, {"stroke-width", "1mm"}}));
    EXPECT_EQ(d.shapes[2].kind, ShapeKind::Circle);
    EXPECT_TRUE(d.hasVertices);
    EXPECT_EQ(d.min, (Vec2{1, -1}));
    EXPECT_EQ(d.max, (Vec2{3, 2}));
}

TEST(GraphDrawing, SvgAttributesOverrideTheDefaultsWithDashedNames) {
    Scene s;
    s.vertex(0, 0, {{".svg_stroke_width", Value(0)}, {".svg_fill_opacity", Value(0.0)}, {".svg_filter", Value("glow")},
                    {".svg_in_", Value("x")}, {"label", Value("not drawn")}, {".svgx_other", Value(1)}});
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].attributes, list({{"fill", "none"},
                                            {"fill-opacity", "0.0"},
                                            {"filter", "url(#glow)"},
                                            {"in", "x"},
                                            {"r", "0.4cm"},
                                            {"stroke", "black"},
                                            {"stroke-width", "0"}}));
}

TEST(GraphDrawing, RectIsCentredWithModelUnitSizes) {
    Scene s;
    s.vertex(1, 1, {{".svg_tag", Value("rect")}});
    s.vertex(2, 2, {{".svg_tag", Value("rect")}, {".svg_width", Value("0.5")}, {".svg_height", Value(2)}, {".svg_fill", Value("red")}});
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 2u);
    EXPECT_EQ(d.shapes[0].kind, ShapeKind::Rect);
    EXPECT_EQ(d.shapes[0].width, kDefaultRectSize);
    EXPECT_EQ(d.shapes[0].height, kDefaultRectSize);
    EXPECT_TRUE(d.shapes[0].attributes.empty());
    EXPECT_EQ(d.shapes[1].centre, (Vec2{2, 2}));
    EXPECT_EQ(d.shapes[1].width, 0.5);
    EXPECT_EQ(d.shapes[1].height, 2);
    EXPECT_EQ(d.shapes[1].attributes, list({{"fill", "red"}}));  // width and height are geometry, not attributes
}

TEST(GraphDrawing, PathCircleAndImageTags) {
    Scene s;
    s.vertex(0, 0, {{".svg_tag", Value("path")}, {".svg_d", Value("M 0 0 L 10 10")}});
    s.vertex(1, 0, {{".svg_tag", Value("circle")}, {".svg_r", Value("3cm")}});
    s.vertex(2, 0, {{".svg_tag", Value("image")}, {".svg_href", Value("brush.png")}, {".svgx_rotate", Value(30)}});
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 3u);
    EXPECT_EQ(d.shapes[0].kind, ShapeKind::Path);
    EXPECT_EQ(d.shapes[0].attributes, list({{"d", "M 0 0 L 10 10"}}));
    EXPECT_EQ(d.shapes[1].kind, ShapeKind::Circle);
    EXPECT_EQ(d.shapes[1].attributes, list({{"r", "3cm"}, {"stroke-width", "0.1mm"}}));
    EXPECT_EQ(d.shapes[2].kind, ShapeKind::Image);
    EXPECT_EQ(d.shapes[2].width, kDefaultImageSize);
    EXPECT_EQ(d.shapes[2].height, kDefaultImageSize);
    EXPECT_EQ(d.shapes[2].rotation, 30);
    EXPECT_EQ(d.shapes[2].attributes, list({{"xlink:href", "brush.png"}}));
}

TEST(GraphDrawing, NoneInEverySpellingDrawsNothing) {
    Scene s;
    const ElementId a = s.vertex(0, 0, {{".svg_tag", Value()}});
    const ElementId b = s.vertex(5, 5, {{".svg_tag", Value("None")}});
    s.edge(a, b, {{".svg_tag", Value("none")}});
    const Drawing d = s.draw();
    EXPECT_TRUE(d.shapes.empty());
    EXPECT_EQ(d.max, (Vec2{5, 5}));  // they still span the canvas
}

TEST(GraphDrawing, AnEdgeWithAnEmptyEndDrawsNothing) {
    Scene s;
    const ElementId a = s.vertex(0, 0, {{".svg_tag", Value("None")}});
    s.edge(a, kNoVertex);
    s.edge(kNoVertex, kNoVertex, {{".svg_tag", Value("path")}, {".svg_d", Value("M 0 0 L 1 1")}});
    EXPECT_TRUE(s.draw().shapes.empty());
}

TEST(GraphDrawing, HelperVerticesAreNeitherDrawnNorOnTheCanvas) {
    Scene s;
    s.vertex(0, 0);
    s.vertex(100, 100, {{".helper_node", Value(true)}});
    const Drawing d = s.draw();
    EXPECT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.max, (Vec2{0, 0}));
}

TEST(GraphDrawing, GeometryAttributesStayTheShapes) {
    Scene s;
    s.vertex(1, 1, {{".svg_cx", Value(99)}, {".svg_width", Value(3)}});
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].centre, (Vec2{1, 1}));
    EXPECT_EQ(d.shapes[0].attribute("cx"), nullptr);
    ASSERT_NE(d.shapes[0].attribute("width"), nullptr);  // a circle has no width: the attribute passes
    EXPECT_EQ(*d.shapes[0].attribute("width"), "3");
}

TEST(GraphDrawing, AnEdgesCentredShapeSitsBetweenItsEnds) {
    Scene s;
    const ElementId a = s.vertex(0, 0, {{".svg_tag", Value("None")}});
    s.edge(a, s.vertex(2, 4, {{".svg_tag", Value("None")}}), {{".svg_tag", Value("rect")}});
    const Drawing d = s.draw();
    ASSERT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].centre, (Vec2{1, 2}));
}

TEST(GraphDrawing, CanvasIsTheVerticesBoxWithAMargin) {
    Scene s;
    s.vertex(-1, 2);
    s.vertex(3, 4);
    const Drawing d = s.draw();
    const DrawingCanvas exact = canvasOf(d, 0);
    EXPECT_DOUBLE_EQ(exact.x, -1 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(exact.y, -4 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(exact.width, 4 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(exact.height, 2 * kUserUnitsPerModelUnit);
    const DrawingCanvas wide = canvasOf(d, 0.5);
    EXPECT_DOUBLE_EQ(wide.x, -1.5 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(wide.y, -4.5 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(wide.width, 5 * kUserUnitsPerModelUnit);
    EXPECT_DOUBLE_EQ(wide.height, 3 * kUserUnitsPerModelUnit);
}

void expectRefused(Scene& s, const std::string& part) {
    try {
        s.draw();
        ADD_FAILURE() << "no error; expected one mentioning " << part;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("scene.yml"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(GraphDrawing, RefusesUnknownTagsBadSizesAndScripts) {
    Scene unknown;
    unknown.vertex(0, 0, {{".svg_tag", Value("ellipse")}});
    expectRefused(unknown, "vertex 0: .svg_tag is 'ellipse'");
    Scene lineVertex;
    lineVertex.vertex(0, 0, {{".svg_tag", Value("line")}});
    expectRefused(lineVertex, "vertex 0: .svg_tag is 'line'");
    Scene size;
    size.vertex(0, 0, {{".svg_tag", Value("rect")}, {".svg_width", Value("wide")}});
    expectRefused(size, ".svg_width is 'wide'");
    Scene script;
    script.vertex(0, 0, {{".svg_onload", Value("alert(1)")}});
    expectRefused(script, "event handler");
    Scene name;
    name.vertex(0, 0, {{".svg_a b", Value(1)}});
    expectRefused(name, "not an XML attribute name");
}

}  // namespace drawing_test
