// Image targets drawn from meshes (issue 14, line 4): a box's shadow straight down is exactly
// the pixels whose centres lie in its footprint; the PNG written loads as an image target with
// those pixels as hits and the rest as avoid; a custom pixel rule gets grey levels it reads the
// same way; a mesh out of view and an existing output are refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "../mesh/cube_mesh.hpp"
#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "score/image/mesh_image_target.hpp"

namespace shapevo {
namespace {

using test::boxMesh;
using test::TempDir;

Camera groundCamera() {
    CameraSpec spec;
    spec.projection = Projection::Shadow;
    spec.width = 40;
    spec.height = 40;
    spec.light = {0.0, -1.0, 0.0};
    spec.groundY = 0.0;
    spec.groundMin = {-2.0, -2.0};
    spec.groundMax = {2.0, 2.0};
    return Camera::compile(spec, "test");
}

TEST(MeshImageTarget, BoxShadowStraightDownIsItsFootprint) {
    // Pixel centres at -1.95, -1.85, ... 1.95 (0.1 apart); |x| <= 0.93 holds 18 of them per axis.
    const Mesh box = boxMesh({-0.93f, 0.5f, -0.3f}, {0.93f, 2.5f, 0.63f});
    const std::vector<std::uint8_t> mask = meshSilhouette(box, groundCamera());
    std::uint64_t count = 0, mismatches = 0;
    for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i) {
            const double x = -2.0 + 0.1 * (i + 0.5), z = -2.0 + 0.1 * (j + 0.5);
            const bool want = std::abs(x) <= 0.93 && z >= -0.3 && z <= 0.63;
            count += mask[std::size_t(j) * 40 + std::size_t(i)];
            mismatches += want != bool(mask[std::size_t(j) * 40 + std::size_t(i)]);
        }
    EXPECT_EQ(count, 18u * 9u);  // z centres -0.25 .. 0.55
    EXPECT_EQ(mismatches, 0u);
}

TEST(MeshImageTarget, WrittenPictureLoadsAsTheSameHitPixels) {
    TempDir dir;
    const std::string png = dir.file("shadow.png");
    const Mesh box = boxMesh({-0.93f, 0.5f, -0.93f}, {0.93f, 2.5f, 0.93f});
    const Camera camera = groundCamera();
    EXPECT_EQ(writeMeshImageTarget(box, camera, PixelRule{}, "box.obj", "cfg.toml", png), 324u);
    const ImageTarget t = loadImageTarget(png, PixelRule{}, 40, 40);
    EXPECT_EQ(t.hitCount, 324u);
    EXPECT_EQ(t.avoidCount, 1600u - 324u);
    const std::vector<std::uint8_t> mask = meshSilhouette(box, camera);
    for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i) ASSERT_EQ(t.isHit(i, j), bool(mask[std::size_t(j) * 40 + std::size_t(i)])) << i << ", " << j;

    // An inverted rule (light = hit, dark = avoid) gets an inverted picture it reads the same way.
    PixelRule inverted;
    inverted.hitMin = 200, inverted.hitMax = 255, inverted.avoidMin = 0, inverted.avoidMax = 50;
    const std::string light = dir.file("light.png");
    writeMeshImageTarget(box, camera, inverted, "box.obj", "cfg.toml", light);
    const ImageTarget u = loadImageTarget(light, inverted, 40, 40);
    EXPECT_EQ(u.hitCount, 324u);
    EXPECT_EQ(u.avoidCount, 1600u - 324u);
}

TEST(MeshImageTarget, OutOfViewMeshAndExistingOutputAreRefused) {
    TempDir dir;
    const Camera camera = groundCamera();
    const std::string png = dir.file("a.png");
    // Entirely below the ground: no shadow.
    EXPECT_THROW(writeMeshImageTarget(boxMesh({-1, -3, -1}, {1, -1, 1}), camera, PixelRule{}, "low.obj", "cfg.toml", png), InputError);
    EXPECT_FALSE(std::filesystem::exists(png));
    test::writeFile(png, "mine");
    EXPECT_THROW(writeMeshImageTarget(boxMesh({-1, 1, -1}, {1, 2, 1}), camera, PixelRule{}, "box.obj", "cfg.toml", png), InputError);
    EXPECT_EQ(test::readFile(png), "mine");
}

}  // namespace
}  // namespace shapevo
