// Cameras for image targets: the three projections agree with independent constructions
// (glm's lookAt/perspective, hand-computed shadows), the near plane / ground decide what is
// seen, and every bad setting is an InputError naming its config key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "base/input_error.hpp"
#include "score/image/camera.hpp"

namespace shapevo {
namespace {

Camera compile(const CameraSpec& s) { return Camera::compile(s, "run.toml"); }

TEST(ImageCamera, PerspectiveMatchesGlmLookAtAndPerspective) {
    CameraSpec s;
    s.eye = {3.0, 4.0, 9.0};
    s.lookAt = {0.5, 1.0, -0.25};
    s.up = {0.2, 1.0, 0.1};
    s.fovDegrees = 60.0;
    const Camera c = compile(s);
    const glm::dmat4 view = glm::lookAt(s.eye, s.lookAt, s.up);
    const glm::dmat4 proj = glm::perspective(glm::radians(60.0), 800.0 / 600.0, 0.1, 100.0);
    for (const glm::dvec3 p : {glm::dvec3(0.0), glm::dvec3(1, 2, 3), glm::dvec3(-2, 0.5, 1), glm::dvec3(0.5, 1.0, -0.25)}) {
        const glm::dvec4 clip = proj * view * glm::dvec4(p, 1.0);
        const double ndcX = clip.x / clip.w, ndcY = clip.y / clip.w;
        const glm::dvec2 expected((ndcX + 1.0) * 0.5 * 800.0, (1.0 - ndcY) * 0.5 * 600.0);  // rows from the top
        const glm::dvec2 got = c.project(p);
        EXPECT_NEAR(got.x, expected.x, 1e-9);
        EXPECT_NEAR(got.y, expected.y, 1e-9);
    }
    const glm::dvec2 centre = c.project(s.lookAt);
    EXPECT_NEAR(centre.x, 400.0, 1e-9);
    EXPECT_NEAR(centre.y, 300.0, 1e-9);
}

TEST(ImageCamera, VerticalFieldOfViewSpansThePictureHeight) {
    CameraSpec s;  // eye (0, 0, 10) looking at the origin, up +y, 60 degrees
    const Camera c = compile(s);
    const double h = 10.0 * std::tan(M_PI / 6.0);
    EXPECT_NEAR(c.project({0.0, h, 0.0}).y, 0.0, 1e-9);    // top edge
    EXPECT_NEAR(c.project({0.0, -h, 0.0}).y, 600.0, 1e-9);  // bottom edge
    EXPECT_NEAR(c.project({h, 0.0, 0.0}).x, 400.0 + 300.0, 1e-9);  // square pixels: +x to the right
}

TEST(ImageCamera, NearPlaneDecidesWhatIsVisible) {
    CameraSpec s;
    s.near = 0.5;
    const Camera c = compile(s);
    EXPECT_TRUE(c.visible({0.0, 0.0, 9.5}));
    EXPECT_FALSE(c.visible({0.0, 0.0, 9.6}));
    EXPECT_FALSE(c.visible({3.0, 0.0, 11.0}));  // behind the eye
    s.projection = Projection::Orthographic;
    const Camera o = compile(s);
    EXPECT_TRUE(o.visible({100.0, 0.0, 9.5}));
    EXPECT_FALSE(o.visible({0.0, 0.0, 9.6}));
}

TEST(ImageCamera, OrthographicViewHeightSpansThePictureHeight) {
    CameraSpec s;
    s.projection = Projection::Orthographic;
    s.viewHeight = 6.0;
    s.eye = {1.0, 2.0, 10.0};
    s.lookAt = {1.0, 2.0, 0.0};
    const Camera c = compile(s);
    EXPECT_NEAR(c.project({1.0, 2.0, -50.0}).x, 400.0, 1e-9);  // depth does not matter
    EXPECT_NEAR(c.project({1.0, 5.0, 3.0}).y, 0.0, 1e-9);
    EXPECT_NEAR(c.project({1.0, -1.0, 3.0}).y, 600.0, 1e-9);
    EXPECT_NEAR(c.project({1.0 + 4.0, 2.0, 0.0}).x, 400.0 + 400.0, 1e-9);
}

TEST(ImageCamera, ShadowFollowsTheLightOntoTheGroundRectangle) {
    CameraSpec s;
    s.projection = Projection::Shadow;
    s.width = 200, s.height = 100;
    s.light = {1.0, -2.0, -0.5};
    s.groundY = -1.0;
    s.groundMin = {-10.0, 0.0};
    s.groundMax = {10.0, 10.0};
    const Camera c = compile(s);
    EXPECT_FALSE(c.groundExtended());
    // (0, 3, 2) is 4 above the ground: the ray travels 4 / 2 = 2 light lengths -> (2, -1, 1).
    const glm::dvec2 p = c.project({0.0, 3.0, 2.0});
    EXPECT_NEAR(p.x, (2.0 + 10.0) / 20.0 * 200.0, 1e-9);
    EXPECT_NEAR(p.y, (1.0 - 0.0) / 10.0 * 100.0, 1e-9);
    const glm::dvec2 g = c.project({-10.0, -1.0, 10.0});  // on the ground: its own position
    EXPECT_NEAR(g.x, 0.0, 1e-9);
    EXPECT_NEAR(g.y, 100.0, 1e-9);
    EXPECT_TRUE(c.visible({0.0, -1.0, 0.0}));
    EXPECT_FALSE(c.visible({0.0, -1.001, 0.0}));  // below the ground casts nothing
}

TEST(ImageCamera, ShadowGroundRectangleIsExtendedAboutItsCentreToSquarePixels) {
    CameraSpec s;
    s.projection = Projection::Shadow;
    s.light = {0.0, -1.0, 0.0};
    s.width = 200, s.height = 100;  // 2 : 1
    s.groundMin = {-2.0, 1.0}, s.groundMax = {2.0, 5.0};  // 1 : 1 -> x is extended to -4..4
    Camera c = compile(s);
    EXPECT_TRUE(c.groundExtended());
    EXPECT_EQ(c.groundMin(), glm::dvec2(-4.0, 1.0));
    EXPECT_EQ(c.groundMax(), glm::dvec2(4.0, 5.0));
    EXPECT_NEAR(c.project({-4.0, 0.0, 1.0}).x, 0.0, 1e-9);
    EXPECT_NEAR(c.project({4.0, 0.0, 5.0}).x, 200.0, 1e-9);
    EXPECT_NEAR(c.project({4.0, 0.0, 5.0}).y, 100.0, 1e-9);
    const glm::dvec2 a = c.project({0.0, 0.0, 3.0}), b = c.project({1.0, 0.0, 4.0});
    EXPECT_NEAR(b.x - a.x, b.y - a.y, 1e-9);  // one world unit is as many pixels across as down
    s.width = 100, s.height = 300;  // 1 : 3 -> z is extended to 3 -+ 6
    c = compile(s);
    EXPECT_TRUE(c.groundExtended());
    EXPECT_EQ(c.groundMin(), glm::dvec2(-2.0, -3.0));
    EXPECT_EQ(c.groundMax(), glm::dvec2(2.0, 9.0));
    s.width = 4000, s.height = 4001;  // within 0.1 %: kept as given
    c = compile(s);
    EXPECT_FALSE(c.groundExtended());
    EXPECT_EQ(c.groundMin(), s.groundMin);
}

/// The "where" of the InputError that compiling `s` throws ("accepted" if none).
std::string whereOf(const CameraSpec& s) {
    try {
        Camera::compile(s, "run.toml", "camera");
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "run.toml");
        return e.where();
    }
    return "accepted";
}

TEST(ImageCamera, BadSettingsAreErrorsNamingTheKey) {
    const CameraSpec good;
    EXPECT_EQ(whereOf(good), "accepted");
    CameraSpec s = good;
    s.lookAt = s.eye;
    EXPECT_EQ(whereOf(s), "camera.look_at");
    s = good, s.up = glm::dvec3(0.0);
    EXPECT_EQ(whereOf(s), "camera.up");
    s = good, s.up = glm::dvec3(0.0, 0.0, -3.0);  // parallel to eye -> look_at
    EXPECT_EQ(whereOf(s), "camera.up");
    for (double fov : {0.0, -10.0, 180.0, 200.0, double(NAN)}) {
        s = good, s.fovDegrees = fov;
        EXPECT_EQ(whereOf(s), "camera.fov_degrees") << fov;
    }
    s = good, s.near = 0.0;
    EXPECT_EQ(whereOf(s), "camera.near");
    s = good, s.width = 0;
    EXPECT_EQ(whereOf(s), "camera.width");
    s = good, s.height = 20000;
    EXPECT_EQ(whereOf(s), "camera.height");
    s = good, s.eye.x = INFINITY;
    EXPECT_EQ(whereOf(s), "camera.eye");
    s = good, s.projection = Projection::Orthographic, s.viewHeight = 0.0;
    EXPECT_EQ(whereOf(s), "camera.view_height");
    s = good, s.projection = Projection::Orthographic, s.fovDegrees = 0.0;  // not used: fine
    EXPECT_EQ(whereOf(s), "accepted");
}

TEST(ImageCamera, BadShadowSettingsAreErrorsNamingTheKey) {
    CameraSpec good;
    good.projection = Projection::Shadow;
    good.eye = good.lookAt;  // not used by shadows
    EXPECT_EQ(whereOf(good), "accepted");
    CameraSpec s = good;
    s.light = glm::dvec3(0.0);
    EXPECT_EQ(whereOf(s), "camera.light");
    s = good, s.light = {1.0, 0.0, 0.0};  // parallel to the ground
    EXPECT_EQ(whereOf(s), "camera.light");
    s = good, s.light = {0.0, 1.0, 0.0};  // pointing up
    EXPECT_EQ(whereOf(s), "camera.light");
    s = good, s.groundMax = {5.0, -5.0};  // empty in z
    EXPECT_EQ(whereOf(s), "camera.ground_max");
    s = good, s.groundMin = {5.0, -5.0};  // empty in x
    EXPECT_EQ(whereOf(s), "camera.ground_max");
    s = good, s.groundY = NAN;
    EXPECT_EQ(whereOf(s), "camera.ground_y");
}

}  // namespace
}  // namespace shapevo
