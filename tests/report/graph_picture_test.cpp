// Tests of report/graph_picture: a Drawing painted as an SVG renderer paints it — a thick black
// line dark along its middle and white beyond its butt ends, a default vertex circle a ring (no
// fill), a rect filled black by default and red when asked, fill-opacity blending, a quadratic
// path stroked through its curve, an image as a grey placeholder, the canvas fitted into another
// size, and the natural size (one pixel per user unit).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "graph/drawing.hpp"
#include "report/graph_picture.hpp"

namespace graph_picture_test {

using namespace shapevo;
using namespace shapevo::graph;

constexpr double kUnit = kUserUnitsPerModelUnit;

/// A drawing whose canvas is the model square [0, 4] x [0, 4] (141.7 user units a side).
Drawing square() {
    Drawing d;
    d.hasVertices = true;
    d.min = {0, 0};
    d.max = {4, 4};
    return d;
}

struct Picture {
    PictureSize size;
    std::vector<std::uint8_t> rgba;
    /// The pixel under model point (x, y) when the picture shows the canvas 1:1 in user units.
    std::array<int, 3> atModel(double x, double y) const { return at(int(x * kUnit), int((4 - y) * kUnit)); }
    std::array<int, 3> at(int px, int py) const {
        const std::size_t i = (std::size_t(py) * std::size_t(size.width) + std::size_t(px)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2]};
    }
};

Picture paint(const Drawing& d, PictureSize size = {142, 142}) { return {size, paintDrawing(d, canvasOf(d, 0), size)}; }

Shape shape(ShapeKind kind, std::vector<DrawAttribute> attributes) {
    Shape s;
    s.kind = kind;
    s.attributes = std::move(attributes);
    return s;
}

const std::array<int, 3> kWhite{255, 255, 255};
const std::array<int, 3> kBlack{0, 0, 0};

TEST(GraphPicture, ThickLineIsDarkInTheMiddleAndEndsButt) {
    Drawing d = square();
    Shape line = shape(ShapeKind::Line, {{"stroke", "black"}, {"stroke-width", "10"}});
    line.end1 = {1, 2};
    line.end2 = {3, 2};
    d.shapes.push_back(line);
    const Picture p = paint(d);
    EXPECT_EQ(p.atModel(2, 2), kBlack);
    EXPECT_EQ(p.atModel(2, 2.1), kBlack);                           // 3.5 user units off the axis: inside 5
    EXPECT_EQ(p.atModel(2, 2.25), kWhite);                          // 8.9 off: outside
    EXPECT_EQ(p.at(int(3 * kUnit) + 3, int(2 * kUnit)), kWhite);    // beyond the butt end
    EXPECT_EQ(p.at(2, 2), kWhite);                                  // the background
}

TEST(GraphPicture, DefaultVertexCircleIsARingAndCssLengthsAreAt96Dpi) {
    Drawing d = square();
    Shape c = shape(ShapeKind::Circle, {{"fill", "none"}, {"r", "1cm"}, {"stroke", "black"}, {"stroke-width", "1mm"}});
    c.centre = {2, 2};
    d.shapes.push_back(c);
    const Picture p = paint(d);
    EXPECT_EQ(p.atModel(2, 2), kWhite);  // no fill
    const double r = 96 / 2.54;          // 1cm in user units
    const auto ring = p.at(int(2 * kUnit + r), int(2 * kUnit));
    EXPECT_LT(ring[0], 128) << "the ring at 37.8 user units from the centre";
    EXPECT_EQ(p.at(int(2 * kUnit + r + 4), int(2 * kUnit)), kWhite);
}

TEST(GraphPicture, RectsFillBlackByDefaultAndInTheirColour) {
    Drawing d = square();
    Shape a = shape(ShapeKind::Rect, {});
    a.centre = {1, 1};
    a.width = a.height = 1;
    Shape b = shape(ShapeKind::Rect, {{"fill", "#f00"}});
    b.centre = {3, 3};
    b.width = b.height = 1;
    Shape c = shape(ShapeKind::Rect, {{"fill", "blue"}, {"fill-opacity", "0.5"}});
    c.centre = {1, 3};
    c.width = c.height = 1;
    d.shapes = {a, b, c};
    const Picture p = paint(d);
    EXPECT_EQ(p.atModel(1, 1), kBlack);
    EXPECT_EQ(p.atModel(3, 3), (std::array<int, 3>{255, 0, 0}));
    const auto half = p.atModel(1, 3);
    EXPECT_NEAR(half[0], 127, 2);
    EXPECT_NEAR(half[2], 255, 1);
    EXPECT_EQ(p.atModel(3, 1), kWhite);
}

TEST(GraphPicture, QuadraticPathIsStrokedAlongItsCurve) {
    Drawing d = square();
    // In user units (y down, the canvas spans y from -141.7 to 0): from (0, 0) to (141.7, 0) with
    // the control point (70.9, -141.7), so the curve's middle is at (70.9, -70.9), the picture's centre.
    const std::string k4 = std::to_string(4 * kUnit), k2 = std::to_string(2 * kUnit);
    d.shapes.push_back(shape(ShapeKind::Path, {{"d", "M 0 0 Q " + k2 + " -" + k4 + " " + k4 + " 0"},
                                               {"fill", "none"},
                                               {"stroke", "rgb(0, 128, 0)"},
                                               {"stroke-width", "6"}}));
    const Picture p = paint(d);
    EXPECT_EQ(p.at(int(2 * kUnit), int(2 * kUnit)), (std::array<int, 3>{0, 128, 0}));
    EXPECT_EQ(p.at(int(2 * kUnit), int(1 * kUnit)), kWhite);
}

TEST(GraphPicture, ImageIsAGreyPlaceholder) {
    Drawing d = square();
    Shape image = shape(ShapeKind::Image, {{"xlink:href", "brush.png"}});
    image.centre = {2, 2};
    image.width = 2;
    image.height = 1;
    d.shapes.push_back(image);
    const Picture p = paint(d);
    const auto grey = p.atModel(2, 2);
    EXPECT_GT(grey[0], 150);
    EXPECT_LT(grey[0], 250);
    EXPECT_EQ(p.atModel(2, 3), kWhite);
}

TEST(GraphPicture, CanvasIsFittedAndCentred) {
    Drawing d = square();
    Shape a = shape(ShapeKind::Rect, {});
    a.centre = {2, 2};
    a.width = a.height = 4;  // the whole canvas
    d.shapes.push_back(a);
    const Picture p = paint(d, {200, 100});
    EXPECT_EQ(p.at(100, 50), kBlack);
    EXPECT_EQ(p.at(10, 50), kWhite);  // left of the centred 100x100 square
    EXPECT_EQ(p.at(190, 50), kWhite);
}

TEST(GraphPicture, NaturalSizeIsOnePixelPerUserUnit) {
    DrawingCanvas c{0, 0, 309.2, 140};
    EXPECT_EQ(naturalPictureSize(c).width, 310);
    EXPECT_EQ(naturalPictureSize(c).height, 140);
    const DrawingCanvas point{0, 0, 0, 0};
    EXPECT_EQ(naturalPictureSize(point).width, 16);
    const DrawingCanvas huge{0, 0, 100000, 1000};
    EXPECT_EQ(naturalPictureSize(huge).width, kMaxPictureSide);
    EXPECT_LE(naturalPictureSize(huge).height, 100);
}

}  // namespace graph_picture_test
