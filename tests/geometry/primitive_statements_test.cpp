// The primitive statements (cylinder, cone [top], sphere, mesh "file", roof [top (x, z) | gable |
// hip | pyramid], paraboloid) and `terminal { }` blocks:
// what they emit, where, and only on genes without expressed children.
#include <gtest/gtest.h>

#include <filesystem>

#include "../model_stream.hpp"
#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"
#include "../kind_params.hpp"

namespace shapevo {
namespace {

using test::rootOnly;


TEST(PrimitiveStatements, EachStatementEmitsItsKindFillingTheScope) {
    const Grammar g = parseGrammar(
        "start A\n"
        "rule A {\n  size (2, 4, 6)\n  box\n  cylinder\n  cone\n  cone top 0.25\n  cone top 7\n  sphere\n}\n",
        "kinds.grammar");
    Geometry out;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 6u);
    const PrimitiveKind kinds[] = {PrimitiveKind::Box, PrimitiveKind::Cylinder, PrimitiveKind::Cone,
                                   PrimitiveKind::Cone, PrimitiveKind::Cone, PrimitiveKind::Sphere};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(out.primitives[i].kind, kinds[i]) << i;
        EXPECT_EQ(out.primitives[i].half, glm::vec3(1, 2, 3)) << i;
    }
    EXPECT_EQ(test::taperOf(out.primitives[2]), 0.0f);   // `cone` alone is pointed
    EXPECT_EQ(test::taperOf(out.primitives[3]), 0.25f);
    EXPECT_EQ(test::taperOf(out.primitives[4]), 1.0f);   // clamped to [0, 1]
    for (const Primitive& p : out.primitives)  // only cones have parameters here; the others' block stays zero
        if (p.kind != PrimitiveKind::Cone) {
            EXPECT_EQ(p.params, KindParams{});
        }
    EXPECT_EQ(out.meshes, &g.meshes);
}

TEST(PrimitiveStatements, EachRoofFormGivesItsTopFractionsFromTheScope) {
    const Grammar g = parseGrammar(
        "start A\n"
        "rule A {\n"
        "  size (4, 2, 2)\n"               // half (2, 1, 1): x is the longer horizontal axis
        "  roof\n"
        "  roof gable\n"
        "  roof hip\n"
        "  roof pyramid\n"
        "  roof top (0.25, 0.75)\n"
        "  roof top (scope.size.x / 8, -1)\n"
        "  roof top (2, 0 / 0)\n"
        "  size (2, 2, 6)\n"               // half (1, 1, 3): z is longer
        "  roof gable\n"
        "  roof hip\n"
        "  size (3, 1, 3)\n"               // a tie
        "  roof gable roof hip\n"
        "  paraboloid\n"
        "  box\n"
        "  roof\n"                          // `roof` alone before the end of the rule
        "}\n",
        "roofs.grammar");
    Geometry out;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::Complete);
    struct Want {
        PrimitiveKind kind;
        float tx, tz;
    };
    const PrimitiveKind R = PrimitiveKind::Roof;
    const Want want[] = {{R, 1, 0},     {R, 1, 0},    {R, 0.5f, 0},         {R, 0, 0},
                         {R, 0.25f, 0.75f}, {R, 0.5f, 0}, {R, 1, 0},        // clamped; NaN -> 0
                         {R, 0, 1},     {R, 0, 1.0f - 1.0f / 3.0f},          // ridge along z, shortened by 1 at both ends
                         {R, 1, 0},     {R, 0, 0},                           // a tie: ridge along x; a square hip is a pyramid
                         {PrimitiveKind::Paraboloid, 1, 1}, {PrimitiveKind::Box, 1, 1}, {R, 1, 0}};
    ASSERT_EQ(out.primitives.size(), std::size(want));
    for (std::size_t i = 0; i < std::size(want); ++i) {
        EXPECT_EQ(out.primitives[i].kind, want[i].kind) << i;
        EXPECT_EQ(test::taperOf(out.primitives[i]), want[i].tx) << i;
        EXPECT_EQ(test::taperZOf(out.primitives[i]), want[i].tz) << i;
    }
    EXPECT_EQ(out.primitives[0].half, glm::vec3(2, 1, 1));
    EXPECT_EQ(out.primitives[12].half, glm::vec3(1.5f, 0.5f, 1.5f));
}

TEST(PrimitiveStatements, RoofTopFractionsAreExpressionsOfTheGenesParameters) {
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  param t = uniform(0.2, 0.8)\n  roof top (t, 1 - t)\n  child A prob 0.5\n}\n", "roof-param.grammar");
    Geometry out;
    DeriveScratch scratch;
    const Chromosome c = rootOnly(g, 9);
    ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 1u);
    const float t = c.param(0, g.rules[0], 0);
    EXPECT_EQ(test::taperOf(out.primitives[0]), t);
    EXPECT_EQ(test::taperZOf(out.primitives[0]), 1 - t);
    EXPECT_GT(t, 0.2f);
}

TEST(PrimitiveStatements, AMansardRoofIsAFrustumWithAHipRoofOnItsTopFace) {
    // the example of grammars/README.md
    const Grammar g = parseGrammar(
        "start A\nrule A {\n"
        "  size (4, 0.6, 3)\n"
        "  roof top (0.8, 0.7)                        # the steep lower part\n"
        "  translate (0, scope.size.y * 0.75, 0)\n"
        "  scale (0.8, 0.5, 0.7)                      # its top face, half as high\n"
        "  roof hip\n"
        "}\n",
        "mansard.grammar");
    Geometry out;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 2u);
    const Primitive &lower = out.primitives[0], &upper = out.primitives[1];
    EXPECT_NEAR(lower.centre.y + lower.half.y, upper.centre.y - upper.half.y, 1e-6f);  // stacked
    EXPECT_NEAR(lower.half.x * test::taperOf(lower), upper.half.x, 1e-6f);                       // on the top face
    EXPECT_NEAR(lower.half.z * test::taperZOf(lower), upper.half.z, 1e-6f);
    EXPECT_NEAR(test::taperOf(upper), 1.0f - 1.05f / 1.6f, 1e-6f);  // hip: along x, shortened by half.z at both ends
    EXPECT_EQ(test::taperZOf(upper), 0.0f);
}

TEST(PrimitiveStatements, TerminalBlockRunsOnlyWithoutExpressedChildrenAndRestoresTheScope) {
    const Grammar g = parseGrammar(
        "start A\n"
        "rule A {\n  child B prob 0.5\n  terminal {\n    translate (0, 5, 0)\n    sphere\n  }\n  box\n}\n"
        "rule B {\n  cylinder\n}\n",
        "terminal.grammar");
    DeriveScratch scratch;
    Geometry out;
    Chromosome c = rootOnly(g);
    ASSERT_EQ(c.genes, 1u);
    ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 2u);  // no children: the sphere, then the box
    EXPECT_EQ(out.primitives[0].kind, PrimitiveKind::Sphere);
    EXPECT_EQ(out.primitives[0].centre, glm::vec3(0, 5, 0));
    EXPECT_EQ(out.primitives[1].kind, PrimitiveKind::Box);
    EXPECT_EQ(out.primitives[1].centre, glm::vec3(0, 0, 0));  // the translate did not leak out

    Rng rng(3);
    appendGene(g, c, std::uint16_t(g.findRule("B")), 0, 0, rng);
    ASSERT_EQ(c.genes, 2u);
    ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 2u);  // a child: no sphere
    for (const Primitive& p : out.primitives) EXPECT_NE(p.kind, PrimitiveKind::Sphere);
}

TEST(PrimitiveStatements, MeshFilesAreReadOnceRelativeToTheGrammarAndNormalized) {
    test::TempDir dir;
    std::filesystem::copy_file(test::sourcePath("grammars/meshes/leaf.obj"), (dir.path() / "leaf.obj").string());
    const std::string text = "start A\nrule A {\n  mesh \"leaf.obj\"\n  scale 2\n  mesh \"leaf.obj\"\n}\n";
    test::writeFile((dir.path() / "leafy.grammar").string(), text);
    const Grammar g = loadGrammar((dir.path() / "leafy.grammar").string());
    ASSERT_EQ(g.meshes.size(), 1u);  // the same file twice is one shape
    float lo = 1, hi = -1;
    for (const glm::vec3& v : g.meshes[0].vertices)
        for (int j = 0; j < 3; ++j) lo = std::min(lo, v[j]), hi = std::max(hi, v[j]);
    EXPECT_EQ(lo, -1.0f);
    EXPECT_EQ(hi, 1.0f);
    Geometry out;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 2u);
    EXPECT_EQ(out.primitives[1].kind, PrimitiveKind::Mesh);
    EXPECT_EQ(test::meshIndexOf(out.primitives[1]), 0);
    EXPECT_EQ(out.primitives[1].half, glm::vec3(1, 1, 1));
}

TEST(PrimitiveStatements, AnOpenMeshIsALocatedError) {
    test::TempDir dir;
    test::writeFile((dir.path() / "open.obj").string(), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    test::writeFile((dir.path() / "g.grammar").string(), "start A\nrule A {\n  mesh \"open.obj\"\n}\n");
    try {
        loadGrammar((dir.path() / "g.grammar").string());
        FAIL() << "an open mesh was accepted";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("g.grammar:3:8: mesh \"open.obj\": "), std::string::npos) << m;
        EXPECT_NE(m.find("open"), std::string::npos) << m;
    }
}

TEST(PrimitiveStatements, ShippedTreeAndCityGrammarsLoadAndDerive) {
    for (const char* name : {"tree.grammar", "city.grammar", "city-filling.grammar"}) {
        const Grammar g = loadGrammar(test::sourcePath(std::string("grammars/") + name));
        Rng rng(5);
        const GenomeLimits limits{400};
        DeriveScratch scratch;
        Geometry out;
        for (int trial = 0; trial < 20; ++trial) {
            Chromosome c;
            while (c.genes < 60 && grow(g, c, rng, limits)) {
            }
            ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete) << name;
            for (const Primitive& p : out.primitives)
                for (int j = 0; j < 3; ++j) ASSERT_TRUE(std::isfinite(p.centre[j]) && p.half[j] >= 0) << name;
        }
    }
}

}  // namespace
}  // namespace shapevo
