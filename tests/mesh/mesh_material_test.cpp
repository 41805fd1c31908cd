// Mesh materials: the sRGB encoding matches IEC 61966-2-1 (known values, both pieces, every byte
// round-trips through the inverse), clamps out-of-range and NaN channels; material names and the
// consistency check accept exactly what the writers can write; grouping keeps mesh order.
#include <gtest/gtest.h>

#include <cmath>

#include "base/input_error.hpp"
#include "cube_mesh.hpp"
#include "mesh/mesh_material.hpp"

namespace shapevo {
namespace {

/// The sRGB decoding (inverse of the encoding), for the round trip.
double srgbToLinear(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }

TEST(SrgbEncoding, KnownValuesOfIec61966) {
    EXPECT_EQ(srgbBytes({0.0f, 1.0f, 0.5f}), (std::array<std::uint8_t, 3>{0, 255, 188}));
    EXPECT_EQ(srgbBytes({0.8f, 0.002f, 0.2158605f}), (std::array<std::uint8_t, 3>{231, 7, 128}));
    EXPECT_NEAR(linearToSrgb(0.002f), 12.92 * 0.002, 1e-7) << "the linear piece";
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045, 1e-5) << "both pieces meet";
    EXPECT_NEAR(linearToSrgb(0.0031309f), 0.04045, 1e-5);
    EXPECT_EQ(srgbHex({1.0f, 0.5f, 0.0f}), "ffbc00");
}

TEST(SrgbEncoding, EveryByteRoundTripsThroughTheDecoding) {
    for (int b = 0; b < 256; ++b) {
        const auto c = float(srgbToLinear(b / 255.0));
        EXPECT_EQ(srgbBytes({c, c, c})[0], b) << "linear " << c;
    }
}

TEST(SrgbEncoding, OutOfRangeAndNanChannelsAreClamped) {
    EXPECT_EQ(srgbBytes({-1.0f, 2.0f, std::nanf("")}), (std::array<std::uint8_t, 3>{0, 255, 0}));
    EXPECT_EQ(clampUnit(0.25f), 0.25f);
    EXPECT_EQ(clampUnit(INFINITY), 1.0f);
    EXPECT_FALSE(std::signbit(clampUnit(-0.0f)));
}

TEST(MaterialNames, OnlyLettersDigitsUnderscoreDashAndDot) {
    for (const char* good : {"a", "steel_2", "color_ff8800", "Wood-Oak.1"}) EXPECT_TRUE(isMaterialName(good)) << good;
    for (const char* bad : {"", "two words", "tab\t", "a#b", "quote\"", "back\\slash", "caf\xc3\xa9"})
        EXPECT_FALSE(isMaterialName(bad)) << bad;
}

Mesh twoMaterialCube() {
    Mesh m = test::cubeMesh(1.0f);
    m.materials = {{"a", {1, 0, 0}}, {"b", {0, 0, 1}}};
    for (std::size_t t = 0; t < m.triangles.size(); ++t) m.triangleMaterials.push_back(t % 3 == 0 ? 1 : 0);
    return m;
}

TEST(CheckMaterials, AcceptsPlainAndConsistentMeshesAndRejectsTheRest) {
    EXPECT_NO_THROW(checkMaterials(test::cubeMesh(1.0f), "m"));
    EXPECT_NO_THROW(checkMaterials(twoMaterialCube(), "m"));
    Mesh orphan = test::cubeMesh(1.0f);
    orphan.triangleMaterials.assign(12, 0);
    EXPECT_THROW(checkMaterials(orphan, "m"), InputError) << "indices without materials";
    Mesh short_ = twoMaterialCube();
    short_.triangleMaterials.pop_back();
    EXPECT_THROW(checkMaterials(short_, "m"), InputError);
    Mesh range = twoMaterialCube();
    range.triangleMaterials[5] = 2;
    EXPECT_THROW(checkMaterials(range, "m"), InputError);
    Mesh twice = twoMaterialCube();
    twice.materials[1].name = "a";
    EXPECT_THROW(checkMaterials(twice, "m"), InputError);
    Mesh badName = twoMaterialCube();
    badName.materials[0].name = "a b";
    EXPECT_THROW(checkMaterials(badName, "m"), InputError);
    for (const float bad : {-0.1f, 1.1f, std::nanf("")}) {
        Mesh colour = twoMaterialCube();
        colour.materials[1].color.z = bad;
        EXPECT_THROW(checkMaterials(colour, "m"), InputError) << bad;
    }
}

TEST(TrianglesByMaterial, EachMaterialListsItsTrianglesInMeshOrder) {
    const auto groups = trianglesByMaterial(twoMaterialCube());
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (std::vector<std::uint32_t>{1, 2, 4, 5, 7, 8, 10, 11}));
    EXPECT_EQ(groups[1], (std::vector<std::uint32_t>{0, 3, 6, 9}));
    const auto plain = trianglesByMaterial(test::cubeMesh(1.0f));
    ASSERT_EQ(plain.size(), 1u);
    EXPECT_EQ(plain[0].size(), 12u);
}

}  // namespace
}  // namespace shapevo
