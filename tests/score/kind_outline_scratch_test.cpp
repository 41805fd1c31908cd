// A kind's own silhouette state (K::OutlineScratch, shape/primitive_kind.hpp) is kept by the outline
// builder, one per kind that declares one, built once from the builder: the cone's frustum and the
// roof's box start as the builder's prism and box, the paraboloid's polyhedron has its rings and
// apex, and a kind without one has an empty placeholder (shape/kinds.hpp's KindOutlineScratch).
#include <gtest/gtest.h>

#include <type_traits>

#include "silhouette_test_util.hpp"

namespace shapevo {
namespace {

TEST(KindOutlineScratch, EachKindWithOneGetsItsOwnBuiltFromTheBuilder) {
    const Camera camera = test::smallTreeCamera();
    OutlineBuilder builder(camera);
    static_assert(std::is_same_v<decltype(builder.scratch<ConeKind>()), ConeKind::OutlineScratch&>);
    static_assert(std::is_same_v<decltype(builder.scratch<RoofKind>()), RoofKind::OutlineScratch&>);
    static_assert(std::is_same_v<decltype(builder.scratch<ParaboloidKind>()), ParaboloidKind::OutlineScratch&>);
    static_assert(std::is_empty_v<std::remove_reference_t<decltype(builder.scratch<BoxKind>())>>);

    const UnitShape& frustum = builder.scratch<ConeKind>().frustum;
    EXPECT_EQ(frustum.vertices, builder.prismShape().vertices);
    EXPECT_EQ(frustum.edges, builder.prismShape().edges);
    EXPECT_EQ(builder.scratch<RoofKind>().roof.vertices, builder.boxShape().vertices);

    const UnitShape& polyhedron = builder.scratch<ParaboloidKind>().polyhedron;
    EXPECT_EQ(polyhedron.rings, kParaboloidRings);
    EXPECT_EQ(polyhedron.ringSize, kRoundSides);
    ASSERT_EQ(polyhedron.vertices.size(), std::size_t(kParaboloidRings * kRoundSides + 1));
    EXPECT_EQ(polyhedron.vertices.back(), glm::dvec3(0.0, 1.0, 0.0));
    for (int i = 0; i < kParaboloidRings; ++i) {
        const glm::dvec3& first = polyhedron.vertices[std::size_t(i * kRoundSides)];  // angle 0: +x
        EXPECT_EQ(first, glm::dvec3(paraboloidRingRadius(i), paraboloidRingHeight(i), 0.0));
    }
    // Each builder has its own: rescaling one builder's frustum leaves another's alone.
    OutlineBuilder other(camera);
    builder.scratch<ConeKind>().frustum.vertices[kRoundSides].x = 0.5;
    EXPECT_EQ(other.scratch<ConeKind>().frustum.vertices, other.prismShape().vertices);
}

}  // namespace
}  // namespace shapevo
