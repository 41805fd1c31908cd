// Model pictures (report/render/): the rasterizer covers what the camera projects, keeps the
// nearest surface whatever the draw order, shades the faces of a cube by the light, shows a
// material's colour, and is deterministic; views and sizes parse or are refused; a contact sheet
// lays out its tiles with labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/input_error.hpp"
#include "report/render/contact_sheet.hpp"
#include "report/render/mesh_renderer.hpp"
#include "report/render/model_picture.hpp"
#include "report/render/view_camera.hpp"
#include "../mesh/cube_mesh.hpp"

namespace shapevo {
namespace {

struct Picture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    Rgba at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
    Rgba at(const glm::vec3& p) const { return at(int(std::floor(p.x)), int(std::floor(p.y))); }
};

Picture draw(const Mesh& mesh, const ViewCamera& camera) {
    Picture p{camera.width, camera.height, std::vector<std::uint8_t>(std::size_t(camera.width * camera.height) * 4)};
    MeshRenderer r;
    r.render(mesh, camera, p.rgba, camera.width);
    return p;
}

Rgba background() { return draw(Mesh{}, frameView(View::Front, {}, 16, 16)).at(0, 0); }

int brightness(Rgba c) { return int(c[0]) + int(c[1]) + int(c[2]); }

Mesh unitCube() { return test::boxMesh(glm::vec3(0.0f), glm::vec3(1.0f)); }

TEST(ModelRender, FrontViewOfAUnitCubeCoversItsProjectedSquare) {
    const Mesh cube = unitCube();
    const ViewCamera cam = frameView(View::Front, boundingSphere(cube), 200, 160);
    const Picture p = draw(cube, cam);
    const glm::vec3 lo = cam.project({0, 1, 1}), hi = cam.project({1, 0, 1});  // top-left, bottom-right corners
    ASSERT_LT(lo.x, hi.x);
    ASSERT_LT(lo.y, hi.y);
    EXPECT_NEAR(hi.x - lo.x, 160 * 0.9 / std::sqrt(3.0), 1e-3) << "the bounding sphere fits the smaller side with a 5 % margin";
    const Rgba bg = background();
    long covered = 0;
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const bool model = p.at(x, y) != bg;
            covered += model;
            const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
            if (cx > lo.x + 1 && cx < hi.x - 1 && cy > lo.y + 1 && cy < hi.y - 1) {
                EXPECT_TRUE(model) << x << "," << y;
            }
            if (cx < lo.x - 1 || cx > hi.x + 1 || cy < lo.y - 1 || cy > hi.y + 1) {
                EXPECT_FALSE(model) << x << "," << y;
            }
        }
    const double side = hi.x - lo.x;
    EXPECT_NEAR(double(covered), side * side, 4 * side + 4) << "within a one-pixel band round the square";
}

/// A triangle in the plane z = `z` covering the middle of a front view, in colour `c`.
void addTriangle(Mesh& m, float z, float size, glm::vec3 colour) {
    const auto v = std::uint32_t(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {{-size, -size, z}, {size, -size, z}, {0.0f, size, z}});
    m.triangles.push_back({v, v + 1, v + 2});
    m.triangleMaterials.push_back(std::uint32_t(m.materials.size()));
    m.materials.push_back({"m" + std::to_string(m.materials.size()), colour});
}

TEST(ModelRender, TheNearerTriangleWinsWhateverTheDrawOrder) {
    for (bool redFirst : {true, false}) {
        Mesh m;
        if (redFirst) addTriangle(m, 0.5f, 1.0f, {1, 0, 0});
        addTriangle(m, -0.5f, 2.0f, {0, 0, 1});  // behind, and larger
        if (!redFirst) addTriangle(m, 0.5f, 1.0f, {1, 0, 0});
        const ViewCamera cam = frameView(View::Front, boundingSphere(m), 120, 120);
        const Picture p = draw(m, cam);
        const Rgba overlap = p.at(cam.project({0, 0, 0})), blueOnly = p.at(cam.project({0, 1.5f, 0}));
        EXPECT_GT(overlap[0], 100) << "red first: " << redFirst;
        EXPECT_EQ(overlap[2], 0) << "red first: " << redFirst;
        EXPECT_EQ(blueOnly[0], 0);
        EXPECT_GT(blueOnly[2], 100);
    }
}

TEST(ModelRender, TrianglesAreDrawnFromBothSides) {
    Mesh m;
    addTriangle(m, 0.0f, 1.0f, {0, 1, 0});
    Mesh flipped = m;
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    const ViewCamera cam = frameView(View::Front, boundingSphere(m), 64, 64);
    EXPECT_EQ(draw(m, cam).rgba, draw(flipped, cam).rgba);
    EXPECT_NE(draw(m, cam).at(cam.project({0, 0, 0})), background());
}

TEST(ModelRender, ThreeQuarterViewShadesTheCubesThreeFacesByTheLight) {
    const Mesh cube = unitCube();
    const ViewCamera cam = frameView(View::ThreeQuarter, boundingSphere(cube), 200, 200);
    const Picture p = draw(cube, cam);
    const int top = brightness(p.at(cam.project({0.5f, 1.0f, 0.5f})));
    const int front = brightness(p.at(cam.project({0.5f, 0.5f, 1.0f})));  // the left face on screen, towards the key light
    const int right = brightness(p.at(cam.project({1.0f, 0.5f, 0.5f})));
    EXPECT_GT(top, front + 30);
    EXPECT_GT(front, right + 30);
    EXPECT_GT(right, 0) << "ambient and fill light the face the key misses";
}

TEST(ModelRender, AMaterialsColourAppearsAndAPlainMeshIsNeutral) {
    Mesh cube = unitCube();
    const ViewCamera cam = frameView(View::Front, boundingSphere(cube), 64, 64);
    const Rgba plain = draw(cube, cam).at(32, 32);
    EXPECT_LE(std::abs(int(plain[0]) - int(plain[2])), 20) << "a neutral colour";
    cube.materials = {{"gold", {0.9f, 0.6f, 0.0f}}};
    cube.triangleMaterials.assign(cube.triangles.size(), 0);
    const Rgba gold = draw(cube, cam).at(32, 32);
    EXPECT_GT(gold[0], gold[1] + 20);
    EXPECT_EQ(gold[2], 0);
    EXPECT_EQ(gold[3], 255);
}

TEST(ModelRender, ATexturedMaterialShowsItsImagesMeanColour) {
    Mesh cube = unitCube();
    cube.materials = {{"bricks", {1.0f, 1.0f, 1.0f}, 0}};
    cube.triangleMaterials.assign(cube.triangles.size(), 0);
    const ViewCamera cam = frameView(View::Front, boundingSphere(cube), 64, 64);
    const Rgba white = draw(cube, cam).at(32, 32);
    const std::string bricks = test::readFile(test::sourcePath("tests/data/bricks.png"));
    cube.textures = {{"bricks.png", std::vector<std::uint8_t>(bricks.begin(), bricks.end())}};
    cube.uvs.assign(cube.vertices.size(), glm::vec2(0.0f));
    const Rgba textured = draw(cube, cam).at(32, 32);
    EXPECT_LT(brightness(textured), brightness(white) - 30) << "not drawn white";
    cube.textures[0].png.resize(20);  // unreadable: the material's own colour
    EXPECT_EQ(draw(cube, cam).at(32, 32), white);
}

TEST(ModelRender, SameModelSameBytesAndAReusedRendererForgetsThePreviousModel) {
    const Mesh cube = unitCube();
    Mesh tri;
    addTriangle(tri, 0.0f, 1.0f, {0, 1, 0});
    const std::array views{View::ThreeQuarter};
    MeshRenderer reused;
    const auto first = renderViews(cube, views, {96, 64}, reused);
    renderViews(tri, views, {96, 64}, reused);
    EXPECT_EQ(renderViews(cube, views, {96, 64}, reused), first);
    MeshRenderer fresh;
    EXPECT_EQ(renderViews(cube, views, {96, 64}, fresh), first);
}

TEST(ModelRender, ThreeViewsSideBySideAreFrontSideAndTop) {
    const Mesh cube = test::boxMesh(glm::vec3(0.0f), glm::vec3(2.0f, 1.0f, 0.5f));
    const auto views = parseViews("three");
    ASSERT_EQ(views, (std::vector<View>{View::Front, View::Side, View::Top}));
    MeshRenderer r;
    const auto rgba = renderViews(cube, views, {50, 40}, r);
    ASSERT_EQ(rgba.size(), std::size_t(150 * 40 * 4));
    // each third equals the single view
    for (std::size_t i = 0; i < views.size(); ++i) {
        const auto one = renderViews(cube, std::span(&views[i], 1), {50, 40}, r);
        for (int y = 0; y < 40; ++y)
            ASSERT_TRUE(std::equal(one.begin() + y * 200, one.begin() + y * 200 + 200, rgba.begin() + (y * 150 + int(i) * 50) * 4))
                << viewName(views[i]) << " row " << y;
    }
}

TEST(ModelRender, ViewAndSizeOptionsParseOrAreRefused) {
    EXPECT_EQ(parseViews("three-quarter"), std::vector<View>{View::ThreeQuarter});
    EXPECT_EQ(parseViews("top"), std::vector<View>{View::Top});
    EXPECT_THROW(parseViews("iso"), InputError);
    EXPECT_THROW(parseViews(""), InputError);
    EXPECT_EQ(parsePictureSize("800x600").width, 800);
    EXPECT_EQ(parsePictureSize("640X480").height, 480);
    for (const char* bad : {"", "800", "800x", "x600", "8x600", "800x-6", "800x600x2", "9000x100", "4097x4097", "1e3x600", " 800x600"})
        EXPECT_THROW(parsePictureSize(bad), InputError) << bad;
}

TEST(ModelRender, AContactSheetHasAGridOfLabelledTiles) {
    ContactSheet sheet(5, {40, 30});
    EXPECT_EQ(sheet.columns(), 3);
    EXPECT_EQ(sheet.width(), 3 * 44 + 4);
    EXPECT_EQ(sheet.height(), 2 * 34 + 4);
    const Mesh cube = unitCube();
    for (int i = 0; i < 4; ++i) sheet.draw(i, cube, std::to_string(7 + i));
    Picture p{sheet.width(), sheet.height(), sheet.pixels()};
    EXPECT_EQ(p.at(0, 0), ContactSheet::kGutterColour);
    EXPECT_EQ(p.at(sheet.tileX(4) + 1, sheet.tileY(4) + 1), background()) << "an undrawn tile is background";
    int dark = 0;  // the label "7" in tile 0's bottom-left corner
    for (int y = sheet.tileY(0) + 20; y < sheet.tileY(0) + 30; ++y)
        for (int x = sheet.tileX(0); x < sheet.tileX(0) + 10; ++x) dark += brightness(p.at(x, y)) < 200;
    EXPECT_GT(dark, 3);
    EXPECT_THROW(ContactSheet(100000, {256, 256}), InputError);
}

}  // namespace
}  // namespace shapevo
