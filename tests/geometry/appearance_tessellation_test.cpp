// Tessellation of looks: Geometry::appearance becomes the mesh's materials, one per distinct
// (clamped colour, material) in order of first use, named after the material or the colour's
// sRGB hex digits and made unique; each triangle gets its primitive's material; a geometry
// without appearance gives a mesh without materials; inconsistent appearance throws.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/tessellation.hpp"

namespace shapevo {
namespace {

Primitive at(PrimitiveKind kind, float x) {
    Primitive p;
    p.kind = kind;
    p.centre = {x, 0.0f, 0.0f};
    return p;
}

/// Triangles each primitive of `g` adds, tessellated alone.
std::vector<std::size_t> trianglesPerPrimitive(const Geometry& g) {
    std::vector<std::size_t> n;
    for (const Primitive& p : g.primitives) {
        Mesh m;
        appendSurface(p, g.meshes, m);
        n.push_back(m.triangles.size());
    }
    return n;
}

const std::vector<std::string> kNames = {"", "steel"};

/// Orange box, steel cylinder, orange sphere (the box's look again), darker steel box.
Geometry colouredModel() {
    Geometry g;
    g.materialNames = &kNames;
    g.primitives = {at(PrimitiveKind::Box, 0), at(PrimitiveKind::Cylinder, 2), at(PrimitiveKind::Sphere, 4),
                    at(PrimitiveKind::Box, 6)};
    g.appearance = {{{1.0f, 0.5f, 0.0f}, 0}, {{0.2f, 0.4f, 0.6f}, 1}, {{1.0f, 0.5f, 0.0f}, 0}, {{0.1f, 0.1f, 0.1f}, 1}};
    return g;
}

TEST(TessellationLooks, WithoutAppearanceTheMeshHasNoMaterials) {
    Geometry g = colouredModel();
    g.appearance.clear();
    const Mesh m = tessellate(g);
    EXPECT_FALSE(m.triangles.empty());
    EXPECT_TRUE(m.materials.empty());
    EXPECT_TRUE(m.triangleMaterials.empty());
}

TEST(TessellationLooks, EachDistinctAppearanceIsOneMaterialInOrderOfFirstUse) {
    const Geometry g = colouredModel();
    const Mesh m = tessellate(g);
    ASSERT_EQ(m.materials.size(), 3u) << "the sphere shares the box's look";
    EXPECT_EQ(m.materials[0], (MeshMaterial{"color_ffbc00", {1.0f, 0.5f, 0.0f}}));
    EXPECT_EQ(m.materials[1], (MeshMaterial{"steel", {0.2f, 0.4f, 0.6f}}));
    EXPECT_EQ(m.materials[2], (MeshMaterial{"steel_2", {0.1f, 0.1f, 0.1f}})) << "same material, another colour";
    ASSERT_EQ(m.triangleMaterials.size(), m.triangles.size());
    const std::vector<std::uint32_t> expected = {0, 1, 0, 2};
    std::size_t t = 0;
    const auto counts = trianglesPerPrimitive(g);
    for (std::size_t p = 0; p < counts.size(); ++p)
        for (std::size_t i = 0; i < counts[p]; ++i, ++t) ASSERT_EQ(m.triangleMaterials[t], expected[p]) << "primitive " << p;
    EXPECT_EQ(t, m.triangles.size());
}

TEST(TessellationLooks, GeometryIsTheSameWithAndWithoutAppearance) {
    Geometry g = colouredModel();
    const Mesh coloured = tessellate(g);
    g.appearance.clear();
    const Mesh plain = tessellate(g);
    EXPECT_EQ(coloured.vertices, plain.vertices);
    EXPECT_EQ(coloured.triangles, plain.triangles);
}

TEST(TessellationLooks, ColoursAreClampedBeforeTheyAreCompared) {
    Geometry g;
    g.primitives = {at(PrimitiveKind::Box, 0), at(PrimitiveKind::Box, 2), at(PrimitiveKind::Box, 4)};
    g.appearance = {{{1.5f, -0.25f, std::nanf("")}, 0}, {{1.0f, 0.0f, 0.0f}, 0}, {{1.0f, -0.0f, 0.0f}, 0}};
    const Mesh m = tessellate(g);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "color_ff0000");
    EXPECT_EQ(m.materials[0].color, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_FALSE(std::signbit(m.materials[0].color.y)) << "no -0 in the files";
}

TEST(TessellationLooks, MaterialNamesKeepOnlyPortableCharactersAndStayUnique) {
    const std::vector<std::string> names = {"", "rusty iron#2", "color_ff0000", "bois_cir\xc3\xa9"};
    Geometry g;
    g.materialNames = &names;
    for (int i = 0; i < 4; ++i) g.primitives.push_back(at(PrimitiveKind::Box, float(2 * i)));
    g.appearance = {{{1, 1, 1}, 1}, {{0, 0, 0}, 2}, {{1, 0, 0}, 0}, {{0, 0, 0}, 3}};
    const Mesh m = tessellate(g);
    ASSERT_EQ(m.materials.size(), 4u);
    EXPECT_EQ(m.materials[0].name, "rusty_iron_2");
    EXPECT_EQ(m.materials[1].name, "color_ff0000") << "a material named like a colour keeps its name";
    EXPECT_EQ(m.materials[2].name, "color_ff0000_2") << "the red colour then takes a suffix";
    EXPECT_EQ(m.materials[3].name, "bois_cir__");
    EXPECT_EQ(appearanceName({{0, 0, 0}, 1}, &names), "rusty_iron_2");
    EXPECT_EQ(appearanceName({{0.5f, 0.8f, 1.0f}, 0}, nullptr), "color_bce7ff");
}

TEST(TessellationLooks, AnEmptyMaterialNameIsNamedByItsColour) {
    const std::vector<std::string> names = {"", ""};
    EXPECT_EQ(appearanceName({{0, 0, 1}, 1}, &names), "color_0000ff");
}

TEST(TessellationLooks, AppearanceCountOrMaterialOutOfRangeThrows) {
    Geometry g = colouredModel();
    g.appearance.pop_back();
    EXPECT_THROW(tessellate(g), std::invalid_argument);
    g = colouredModel();
    g.appearance[2].material = 2;
    EXPECT_THROW(tessellate(g), std::out_of_range);
    g = colouredModel();
    g.materialNames = nullptr;
    EXPECT_THROW(tessellate(g), std::out_of_range) << "material 1 without names";
    g.appearance = {{}, {}, {}, {}};  // all the unnamed default: no names needed
    EXPECT_EQ(tessellate(g).materials.size(), 1u);
}

}  // namespace
}  // namespace shapevo
