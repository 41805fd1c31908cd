// Plain output: a model whose grammar sets no colour or material (Geometry::appearance empty) is
// written exactly as before colours existed. The expected sizes and XXH3-64 hashes of the OBJ,
// PLY and GLB files were taken from the writers of commit 2a9c234 (the last one without
// colours) for a model of boxes and a mesh primitive, whose coordinates are exact in float (no
// trigonometry), so the files are the same on every machine.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "base/hash.hpp"
#include "mesh/glb_writer.hpp"
#include "report/model_writer.hpp"
#include "shape/kinds/mesh.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

/// The octahedron |x| + |y| + |z| <= 1, outward-facing.
MeshShape octahedron() {
    MeshShape s;
    s.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) {
                const bool even = ((x == 0) == (y == 2)) == (z == 4);
                s.triangles.push_back(even ? std::array<std::uint32_t, 3>{x, y, z} : std::array<std::uint32_t, 3>{x, z, y});
            }
    return s;
}

/// Three boxes (plain, mirrored in x, turned a quarter about y) and a mesh primitive.
Geometry exactModel(const std::vector<MeshShape>& meshes) {
    Geometry g;
    g.meshes = &meshes;
    Primitive box;
    box.centre = {0.5f, -1.0f, 2.0f};
    box.half = {0.5f, 1.25f, 0.75f};
    g.primitives.push_back(box);
    Primitive mirrored = box;
    mirrored.centre = {-3.0f, 0.25f, 1.0f};
    mirrored.axes[0] = {-1.0f, 0.0f, 0.0f};
    g.primitives.push_back(mirrored);
    Primitive turned = box;
    turned.centre = {2.0f, 4.0f, -0.5f};
    turned.axes = glm::mat3({0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
    g.primitives.push_back(turned);
    Primitive mesh;
    mesh.kind = PrimitiveKind::Mesh;
    setParams<MeshKind>(mesh, {0});
    mesh.centre = {0.0f, 2.0f, 0.0f};
    mesh.half = {1.0f, 0.5f, 2.0f};
    g.primitives.push_back(mesh);
    return g;
}

struct Golden {
    const char* file;
    std::uint64_t size;
    const char* hash;
};

TEST(PlainOutput, WithoutAppearanceObjPlyAndGlbAreByteIdenticalToTheWritersBeforeColours) {
    const std::vector<MeshShape> meshes = {octahedron()};
    const Geometry model = exactModel(meshes);
    ASSERT_TRUE(model.appearance.empty());
    const Mesh mesh = meshOf(model);
    test::TempDir dir;
    writeObj(mesh, dir.file("m.obj"));
    writePly(mesh, dir.file("m.ply"));
    writeGlb(mesh, dir.file("m.glb"));
    ASSERT_TRUE(mesh.materials.empty());
    const Golden golden[] = {
        {"m.obj", 900, "821a659ba5bb58b8"}, {"m.ply", 1131, "11e86ca64eef7f68"}, {"m.glb", 1504, "2c69a05d7ada189f"}};
    for (const Golden& g : golden) {
        const std::string bytes = test::readFile(dir.file(g.file));
        EXPECT_EQ(bytes.size(), g.size) << g.file;
        EXPECT_EQ(hashHex(hash64(bytes)), g.hash) << g.file;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("m.mtl"))) << "no material file without appearance";
}

TEST(PlainOutput, NeverReplaceWritesTheSameBytesAsAlways) {
    const std::vector<MeshShape> meshes = {octahedron()};
    const Mesh mesh = meshOf(exactModel(meshes));
    test::TempDir dir;
    writeObj(mesh, dir.file("a.obj"));
    writeObj(mesh, dir.file("n.obj"), Replace::Never);
    writePly(mesh, dir.file("a.ply"));
    writePly(mesh, dir.file("n.ply"), Replace::Never);
    writeGlb(mesh, dir.file("a.glb"));
    writeGlb(mesh, dir.file("n.glb"), Replace::Never);
    for (const char* ext : {".obj", ".ply", ".glb"})
        EXPECT_EQ(test::readFile(dir.file(std::string("a") + ext)), test::readFile(dir.file(std::string("n") + ext))) << ext;
}

TEST(PlainOutput, ObjWithoutMaterialsNeitherWritesNorMindsAnExistingMtl) {
    const std::vector<MeshShape> meshes = {octahedron()};
    test::TempDir dir;
    test::writeFile(dir.file("m.mtl"), "someone else's");
    writeObj(meshOf(exactModel(meshes)), dir.file("m.obj"), Replace::Never);
    EXPECT_EQ(test::readFile(dir.file("m.mtl")), "someone else's");
    EXPECT_EQ(test::readFile(dir.file("m.obj")).find("mtllib"), std::string::npos);
}

}  // namespace
}  // namespace shapevo
