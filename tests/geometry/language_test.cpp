// The building statements of the grammar language: rule arguments and instances, let, if / else /
// case, split (absolute, relative, floating, repeat groups), repeat, comp, extrude, lots, colours
// and materials. Each test derives a small grammar and checks the primitives it emits against
// the layout worked out by hand (grammars/README.md states the rules).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

/// The primitives of the root-only derivation of `text` (optional children left out).
Geometry deriveRoot(const std::string& text, std::uint64_t seed = 1, const AttrOverrides& attrs = {}) {
    const Grammar g = parseGrammar(text, "language.grammar", attrs);
    Rng rng(seed);
    Chromosome c;
    plantRoot(g, c, rng);
    Geometry out;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
    out.meshes = nullptr;
    out.materialNames = nullptr;
    return out;
}

/// Lower and upper world x of an axis-aligned primitive.
float lowX(const Primitive& p) { return p.centre.x - p.half.x; }
float highX(const Primitive& p) { return p.centre.x + p.half.x; }

TEST(GrammarLanguage, ConstantArgumentsInstantiateOneRulePerTupleWithPriorsFromTheArguments) {
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  child B(0, 120) prob 0.5\n  child B(120, 240) prob 0.5\n  child B(0, 120) prob 0.5\n}\n"
        "rule B(lo, hi) {\n  param turn = uniform(lo, hi)\n  param s = uniform(lo / 100, hi / 100)\n  box\n}\n",
        "args.grammar");
    ASSERT_EQ(g.rules.size(), 3u);  // A, then B(0, 120) and B(120, 240) in order of first use
    EXPECT_EQ(g.rules[1].name, "B(0, 120)");
    EXPECT_EQ(g.rules[2].name, "B(120, 240)");
    EXPECT_EQ(g.rules[0].slots[0].rules[0], 1);
    EXPECT_EQ(g.rules[0].slots[2].rules[0], 1);  // the same tuple shares its instance
    EXPECT_EQ(g.rules[2].params[0].prior[0].lo, 120.0f);
    EXPECT_EQ(g.rules[2].params[0].prior[0].hi, 240.0f);
    EXPECT_FLOAT_EQ(g.rules[2].params[1].prior[0].hi, 2.4f);
}

TEST(GrammarLanguage, AttrsAreExpressionsAndOverridesReplaceThem) {
    const std::string text = "attr w = 2 * 3\nattr h = w / 2 + 1\nstart A\nrule A {\n  size (w, h, 1)\n  box\n}\n";
    Geometry out = deriveRoot(text);
    ASSERT_EQ(out.primitives.size(), 1u);
    EXPECT_EQ(out.primitives[0].half, glm::vec3(3, 2, 0.5f));
    out = deriveRoot(text, 1, {{"w", 10.0}});
    EXPECT_EQ(out.primitives[0].half, glm::vec3(5, 3, 0.5f));  // h follows the overridden w
    EXPECT_THROW(parseGrammar(text, "x.grammar", {{"nope", 1.0}}), InputError);
}

TEST(GrammarLanguage, IfElseAndCaseChooseBranchesFromTheScope) {
    const std::string text =
        "start A\nrule A {\n  size (4, 1, 2)\n"
        "  if (scope.size.x > scope.size.z) { cylinder } else { sphere }\n"
        "  if (scope.size.x < 1) { box }\n"
        "  case (scope.size.z > 5) { box } case (scope.size.z == 2 && !(scope.size.x == 3)) { cone } else { sphere }\n"
        "  let big = scope.size.x >= 4\n"
        "  if (big) { size 1 box } else if (1) { sphere }\n}\n";
    const Geometry out = deriveRoot(text);
    ASSERT_EQ(out.primitives.size(), 3u);
    EXPECT_EQ(out.primitives[0].kind, PrimitiveKind::Cylinder);
    EXPECT_EQ(out.primitives[1].kind, PrimitiveKind::Cone);
    EXPECT_EQ(out.primitives[2].kind, PrimitiveKind::Box);
    EXPECT_EQ(out.primitives[2].half, glm::vec3(0.5f));
}

TEST(GrammarLanguage, SplitGivesAbsoluteRelativeAndFloatingPiecesInOrderAndFillsTheScope) {
    // 10 units: 2 absolute, 30 % relative (3), two floating ~1 and ~3 share the remaining 5 as 1:3.
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  size (10, 1, 1)\n  split x { 2: { box } | '0.3: { box } | ~1: { box } | ~3: { box } }\n}\n");
    ASSERT_EQ(out.primitives.size(), 4u);
    const float expectLow[] = {-5, -3, 0, 1.25f}, expectHigh[] = {-3, 0, 1.25f, 5};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(lowX(out.primitives[k]), expectLow[k], 1e-5) << k;
        EXPECT_NEAR(highX(out.primitives[k]), expectHigh[k], 1e-5) << k;
    }
}

TEST(GrammarLanguage, RepeatGroupRepeatsAsOftenAsItFitsAndStretchesFloatingPieces) {
    // 10 units, 1-unit borders, a group {~2 tile | 0.5 gap}: 8 / 2.5 = 3 repeats, tiles stretched to 2.1667.
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  size (10, 1, 1)\n  split x { 1: { box } | { ~2: { sphere } | 0.5: nil }* | 1: { box } }\n}\n");
    ASSERT_EQ(out.primitives.size(), 5u);
    int spheres = 0;
    for (const Primitive& p : out.primitives)
        if (p.kind == PrimitiveKind::Sphere) {
            ++spheres;
            EXPECT_NEAR(2 * p.half.x, (8.0f - 1.5f) / 3.0f, 1e-5);
        }
    EXPECT_EQ(spheres, 3);
    EXPECT_NEAR(highX(out.primitives.back()), 5.0f, 1e-5);
}

TEST(GrammarLanguage, SplitCutsPiecesBeyondTheScopeAndEmitsNoZeroSizePieces) {
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  size (3, 1, 1)\n  split x { 2: { box } | 2: { box } | 2: { box } | ~1: { sphere } }\n}\n");
    ASSERT_EQ(out.primitives.size(), 2u);  // the second box is cut to 1, the third and the float get nothing
    EXPECT_NEAR(2 * out.primitives[1].half.x, 1.0f, 1e-6);
}

TEST(GrammarLanguage, RepeatByCountBySizeAndFloating) {
    const Geometry count = deriveRoot("start A\nrule A {\n  size (1, 6, 1)\n  repeat y count 4 { box } | { sphere }\n}\n");
    ASSERT_EQ(count.primitives.size(), 4u);
    EXPECT_EQ(count.primitives[0].kind, PrimitiveKind::Box);
    EXPECT_EQ(count.primitives[1].kind, PrimitiveKind::Sphere);  // successors in turn
    EXPECT_NEAR(count.primitives[3].centre.y, 3 - 0.75f, 1e-6);
    const Geometry bySize = deriveRoot("start A\nrule A {\n  size (7, 1, 1)\n  repeat x 2 { box }\n}\n");
    EXPECT_EQ(bySize.primitives.size(), 3u);  // 3 whole tiles of 2; the last unit stays empty
    const Geometry floating = deriveRoot("start A\nrule A {\n  size (7, 1, 1)\n  repeat x ~2 { box }\n}\n");
    ASSERT_EQ(floating.primitives.size(), 3u);
    EXPECT_NEAR(2 * floating.primitives[0].half.x, 7.0f / 3.0f, 1e-6);
}

TEST(GrammarLanguage, CompFacesAreOutwardFlatScopesAndExtrudeStandsOnThem) {
    // Extruding every face of a 2 x 4 x 6 box by 1 puts a slab outside each face.
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  size (2, 4, 6)\n  comp { top: Slab | bottom: Slab | side: Slab }\n}\n"
        "rule Slab {\n  extrude 1\n  box\n}\n");
    ASSERT_EQ(out.primitives.size(), 6u);
    const glm::vec3 centres[] = {{0, 2.5f, 0}, {0, -2.5f, 0}, {0, 0, 3.5f}, {1.5f, 0, 0}, {0, 0, -3.5f}, {-1.5f, 0, 0}};
    const glm::vec3 halves[] = {{1, 0.5f, 3}, {1, 0.5f, 3}, {1, 2, 0.5f}, {0.5f, 2, 3}, {1, 2, 0.5f}, {0.5f, 2, 3}};
    for (int k = 0; k < 6; ++k) {
        const Primitive& p = out.primitives[std::size_t(k)];
        EXPECT_NEAR(glm::length(p.centre - centres[k]), 0.0f, 1e-5) << k;
        // world half extents of the oriented box
        glm::vec3 world(0);
        for (int a = 0; a < 3; ++a) world += glm::abs(p.axes[a]) * p.half[a];
        EXPECT_NEAR(glm::length(world - halves[k]), 0.0f, 1e-5) << k;
        EXPECT_GT(glm::determinant(p.axes), 0.0f) << k;  // faces keep the frame right-handed
    }
}

TEST(GrammarLanguage, LotsLieOnTheGroundAndCornersAndEdgesFollowTheirCounts) {
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  lot rect (-10, -30, 10, 30) {\n    extrude 5\n    box\n"
        "    comp { bottom: nil | top: { corners (0.2, 0.2) on (1, 0, 1, 0) { extrude 1 cylinder } } }\n  }\n"
        "  lot circle (50, 0, 2) { edges (0.25, 0.25) (1, 2, 0, 3) { extrude 1 sphere } }\n}\n");
    ASSERT_EQ(out.primitives.size(), 1u + 2u + 6u);
    const Primitive& body = *std::find_if(out.primitives.begin(), out.primitives.end(),
                                          [](const Primitive& p) { return p.kind == PrimitiveKind::Box; });
    EXPECT_NEAR(glm::length(body.centre - glm::vec3(0, 2.5f, 0)), 0.0f, 1e-5);  // standing on y = 0
    int cylinders = 0, spheres = 0;
    for (const Primitive& p : out.primitives) {
        if (p.kind == PrimitiveKind::Cylinder) {
            ++cylinders;
            EXPECT_NEAR(p.centre.y, 5.5f, 1e-5);
            EXPECT_NEAR(std::fabs(p.centre.x), 10.0f, 1e-5);  // on the corners of the top face
            EXPECT_NEAR(std::fabs(p.centre.z), 30.0f, 1e-5);
            EXPECT_NEAR(2 * p.half.x, 4.0f, 1e-5);  // min(0.2 * 20, 0.2 * 60)
        }
        if (p.kind == PrimitiveKind::Sphere) ++spheres;
    }
    EXPECT_EQ(cylinders, 2);
    EXPECT_EQ(spheres, 6);
}

TEST(GrammarLanguage, InlineCallsTakeRunTimeArgumentsAndShareOneParameterBlock) {
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  size (6, 1, 1)\n  repeat x count 3 Tile(scope.size.x * 2)\n}\n"
        "rule Tile(w) {\n  param h = uniform(1, 2)\n  size (w, h, 1)\n  box\n}\n",
        "inline.grammar");
    ASSERT_EQ(g.rules.size(), 1u);  // Tile takes arguments and is only ever run inline: no rule of its own
    EXPECT_EQ(g.rules[0].paramFloats, 1u);  // Tile's h lives in A's gene, once for all tiles
    EXPECT_EQ(g.rules[0].params[0].name, "Tile.h");
    Rng rng(3);
    Chromosome c;
    plantRoot(g, c, rng);
    Geometry out;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
    ASSERT_EQ(out.primitives.size(), 3u);
    for (const Primitive& p : out.primitives) {
        EXPECT_NEAR(p.half.x, 2.0f, 1e-6);  // w = the piece's size (2) * 2
        EXPECT_EQ(p.half.y, out.primitives[0].half.y);
    }
}

TEST(GrammarLanguage, PriorsOverTheScopeDrawFromAUnitParameterWithinTheirRunTimeBounds) {
    // The gene stores u in [0, 1]; the value is a + u (b - a) with the bounds of this scope.
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  size (4, 1, 1)\n  param w = uniform(0.25 * scope.size.x, 0.5 * scope.size.x)\n"
        "  param n = int(1, scope.size.x)\n  mirror x\n  split y { ~1: { size (w, n, 1) box } }\n}\n",
        "runtime-prior.grammar");
    const Rule& r = g.rules[0];
    ASSERT_EQ(r.paramFloats, 2u);
    EXPECT_EQ(r.params[0].prior[0].lo, 0.0f);
    EXPECT_EQ(r.params[0].prior[0].hi, 1.0f);
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        Rng rng(seed);
        Chromosome c;
        plantRoot(g, c, rng);
        const float u = c.param(0, r, 0), v = c.param(0, r, 1);
        Geometry out;
        DeriveScratch scratch;
        ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
        ASSERT_EQ(out.primitives.size(), 2u);  // both sides of the mirror see the drawn values
        for (const Primitive& p : out.primitives) {
            EXPECT_FLOAT_EQ(2 * p.half.x, 1.0f + u * (2.0f - 1.0f)) << seed;
            const float n = 2 * p.half.y;
            EXPECT_EQ(n, std::min(std::floor(1.0f + v * 4.0f), 4.0f)) << seed;
            EXPECT_GE(n, 1.0f);
            EXPECT_LE(n, 4.0f);
        }
    }
}

TEST(GrammarLanguage, NormalPriorsOverTheScopeStayInTheirBoundsAndFollowTheQuantile) {
    // value = mu + s Q(F(α) + u (F(β) − F(α))): u = 1/2 of a symmetric support gives mu.
    const Grammar g = parseGrammar(
        "start A\nrule A {\n  size (4, 1, 1)\n  param w = normal(scope.size.x / 2, scope.size.x / 8) in [1, scope.size.x - 1]\n"
        "  size (w, 1, 1)\n  box\n}\n",
        "normal-prior.grammar");
    const Rule& r = g.rules[0];
    Chromosome c;
    Rng rng(5);
    plantRoot(g, c, rng);
    Geometry out;
    DeriveScratch scratch;
    for (float u : {0.0f, 0.001f, 0.25f, 0.5f, 0.75f, 0.999f, 1.0f}) {
        c.setParam(0, r, 0, u);
        ASSERT_EQ(derive(g, c, out, scratch), DeriveStatus::Complete);
        const float w = 2 * out.primitives[0].half.x;
        EXPECT_GE(w, 1.0f) << u;
        EXPECT_LE(w, 3.0f) << u;
        if (u == 0.5f) EXPECT_NEAR(w, 2.0f, 1e-5);
        if (u == 0.0f) EXPECT_NEAR(w, 1.0f, 1e-5);
        if (u == 1.0f) EXPECT_NEAR(w, 3.0f, 1e-5);
    }
    c.setParam(0, r, 0, 0.75f);
    derive(g, c, out, scratch);
    // F(β) = F(2) = 0.97725, F(α) = 0.02275: p = 0.5 + 0.25 * 0.9545 = 0.73863, Q(p) = 0.6398
    EXPECT_NEAR(2 * out.primitives[0].half.x, 2.0f + 0.5f * 0.6398f, 2e-3);
}

TEST(GrammarLanguage, LetValuesSurviveAMirrorAndPiecesThatContinueTheGene) {
    const Geometry out = deriveRoot(
        "start A\nrule A {\n  let w = 3\n  mirror x\n  translate (w, 0, 0)\n  split y { ~1: { size (w, w, w) box } | ~1: nil }\n}\n");
    ASSERT_EQ(out.primitives.size(), 2u);
    for (const Primitive& p : out.primitives) EXPECT_EQ(p.half, glm::vec3(1.5f));
    EXPECT_EQ(out.primitives[0].centre.x, -out.primitives[1].centre.x);
}

TEST(GrammarLanguage, ColoursAndMaterialsAreInheritedAndCostNothingWithoutThem) {
    const Geometry plain = deriveRoot("start A\nrule A {\n  box\n  sphere\n}\n");
    EXPECT_TRUE(plain.appearance.empty());
    const Geometry coloured = deriveRoot(
        "start A\nrule A {\n  box\n  color (1, 0.5, 2)\n  material brick\n  split x { ~1: { sphere } | ~1: { color 0.25 cone } }\n  box\n}\n");
    // Pieces run after the rest of their rule (like children): box, box, then the sphere and the cone.
    ASSERT_EQ(coloured.appearance.size(), 4u);
    EXPECT_EQ(coloured.appearance[0], Appearance{});
    EXPECT_EQ(coloured.appearance[1].color, glm::vec3(1, 0.5f, 1));  // clamped to [0, 1]; the cone's colour stayed in its piece
    EXPECT_EQ(coloured.appearance[1].material, 1u);
    EXPECT_EQ(coloured.appearance[2].color, glm::vec3(1, 0.5f, 1));
    EXPECT_EQ(coloured.appearance[3].color, glm::vec3(0.25f));
    EXPECT_EQ(coloured.appearance[3].material, 1u);  // the material is inherited
}

}  // namespace
}  // namespace shapevo
