// CRL's functions derive what castlemaker-crl.txt §3.7 says, in shapevo's y-up world (CRL
// (x, y, z) = shapevo (x, z, -y)): the transformation matrices of rect, circ, extrude, scale and
// translate; corners anticlockwise from (+X, -Y); edges inside along each edge; lot splits x
// fastest from the low corner; comp's faces from the -Y face anticlockwise, each of unit depth;
// subdiv upwards, split along a face; inserted OBJs upright facing -Y; stochastic rules at their
// probabilities, drawn per piece; several rules of one predecessor all applied; attrs, includes
// and inserted rule files; rand() as evolvable parameters; recursion through optional slots.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include "../test_support.hpp"
#include "genome/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::sourcePath;
using test::TempDir;
using test::writeFile;

/// Parse `text` as a rule file in grammars/castlemaker/ (so data/simple_window.obj resolves).
Grammar rules(const std::string& text, const AttrOverrides& attrs = {}) {
    return parseGrammar(text, sourcePath("grammars/castlemaker/test.rule"), attrs);
}

Geometry deriveOnce(const Grammar& g, std::uint64_t seed = 1) {
    Chromosome c;
    Rng rng(seed);
    EXPECT_TRUE(growUncontrolled(g, c, rng, 1000));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    return geo;
}

void expectVec(const glm::vec3& v, float x, float y, float z, const std::string& what = "") {
    EXPECT_NEAR(v.x, x, 1e-4f) << what;
    EXPECT_NEAR(v.y, y, 1e-4f) << what;
    EXPECT_NEAR(v.z, z, 1e-4f) << what;
}

/// The primitive whose centre is nearest to `at` (derivation order is not the order of the rules).
const Primitive& nearest(const Geometry& geo, const glm::vec3& at) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < geo.primitives.size(); ++i)
        if (glm::length(geo.primitives[i].centre - at) < glm::length(geo.primitives[best].centre - at)) best = i;
    return geo.primitives.at(best);
}

/// The primitives of each material.
std::map<std::string, std::vector<Primitive>> byMaterial(const Grammar& g, const Geometry& geo) {
    std::map<std::string, std::vector<Primitive>> out;
    for (std::size_t i = 0; i < geo.primitives.size(); ++i) out[g.materialNames[geo.appearance[i].material]].push_back(geo.primitives[i]);
    return out;
}

TEST(CrlFunctions, RectExtrudeAndInsertVolumeFillTheThesisBox) {
    const Geometry geo = deriveOnce(rules("L = rect(0, 0, 4, 2);\nL -> extrude(3) {B};\nB -> insert_volume(1, 1, 1, 0, 0, 1);"));
    ASSERT_EQ(geo.primitives.size(), 1u);
    EXPECT_EQ(geo.primitives[0].kind, PrimitiveKind::Box);
    expectVec(geo.primitives[0].centre, 2, 1.5f, -1);  // CRL x 0..4, y 0..2, z 0..3
    expectVec(geo.primitives[0].half, 2, 1.5f, 1);
}

TEST(CrlFunctions, ScaleKeepsTheBaseAndTranslateMovesByFractionsOfTheSize) {
    const Geometry geo = deriveOnce(rules("L = rect(-1, -1, 1, 1);\nL -> extrude(2) {B};\nB -> scale(0.5, 1, 2) {C};\n"
                                          "C -> translate(1, 0.5, 0) {D};\nD -> insert_volume(1, 1, 1, 0, 0, 1);"));
    ASSERT_EQ(geo.primitives.size(), 1u);
    expectVec(geo.primitives[0].half, 0.5f, 2, 1);
    expectVec(geo.primitives[0].centre, 1, 2, -1);  // moved by 1 x 1 along X and 0.5 x 2 along Y; base still at 0
}

TEST(CrlFunctions, CircScalesTheUnitBoxByItsRadiusAsTheMatrixSays) {
    const Geometry geo = deriveOnce(rules("C = circ(5, 2, 4);\nC -> extrude(1) {T};\nT -> insert_cylinder(1, 1, 1, 16);"));
    ASSERT_EQ(geo.primitives.size(), 1u);
    EXPECT_EQ(geo.primitives[0].kind, PrimitiveKind::Cylinder);
    expectVec(geo.primitives[0].centre, 5, 0.5f, -2);
    expectVec(geo.primitives[0].half, 2, 0.5f, 2);
}

TEST(CrlFunctions, CornersGoAnticlockwiseFromPlusXMinusYAndKeepTheHeight) {
    const Grammar g = rules("L = rect(-10, -5, 10, 5);\nL -> extrude(7) {V};\nV -> corners(0.1, 0.2, 1, 1, 0, 1) {A | B};\n"
                            "A -> add_material(\"a\", 1, 0, 0) {AV};\nAV -> insert_volume(1, 1, 1, 0, 0, 1);\n"
                            "B -> add_material(\"b\", 0, 0, 1) {BV};\nBV -> insert_volume(1, 1, 1, 0, 0, 1);");
    auto m = byMaterial(g, deriveOnce(g));
    ASSERT_EQ(m["a"].size(), 2u);  // corners 1 and 4 (the 1st and 3rd switched on)
    ASSERT_EQ(m["b"].size(), 1u);  // corner 2
    if (m["a"][0].centre.x < 0) std::swap(m["a"][0], m["a"][1]);
    expectVec(m["a"][0].centre, 10, 3.5f, 5, "corner 1: (+X, -Y)");
    expectVec(m["b"][0].centre, 10, 3.5f, -5, "corner 2: (+X, +Y)");
    expectVec(m["a"][1].centre, -10, 3.5f, 5, "corner 4: (-X, -Y)");
    expectVec(m["a"][0].half, 1, 3.5f, 1);  // side min(0.1 x 20, 0.2 x 10) = 2, the volume's height
}

TEST(CrlFunctions, EdgesLieInsideAlongEachEdgeAnticlockwiseFromMinusY) {
    const Grammar g = rules("L = rect(0, 0, 10, 20);\nL -> edges(0.1, 0.2, 2, 1, 0, 0) {A | B};\n"
                            "A -> add_material(\"a\", 1, 0, 0) {AV};\nAV -> insert_volume(1, 1, 1, 0, 0, 1);\n"
                            "B -> add_material(\"b\", 0, 0, 1) {BV};\nBV -> insert_volume(1, 1, 1, 0, 0, 1);");
    auto m = byMaterial(g, deriveOnce(g));
    ASSERT_EQ(m["a"].size(), 2u);
    ASSERT_EQ(m["b"].size(), 1u);
    // the -Y edge: lots 0.1 x 10 = 1 wide, 0.2 x 20 = 4 deep, centred at x 2.5 and 7.5, y 2
    if (m["a"][0].centre.x > m["a"][1].centre.x) std::swap(m["a"][0], m["a"][1]);
    expectVec(m["a"][0].centre, 2.5f, 0.5f, -2);
    expectVec(m["a"][1].centre, 7.5f, 0.5f, -2);
    expectVec(m["a"][0].half, 0.5f, 0.5f, 2);
    // the +X edge: x along the edge (CRL +Y), 0.1 x 20 = 2 long, 0.2 x 10 = 2 deep, inside from x = 10
    expectVec(m["b"][0].centre, 9, 0.5f, -10);
    EXPECT_NEAR(std::fabs(glm::dot(m["b"][0].axes[0], glm::vec3(0, 0, -1))), 1.0f, 1e-5f) << "x runs along the edge";
    EXPECT_NEAR(m["b"][0].half.x, 1, 1e-4f);
    EXPECT_NEAR(m["b"][0].half.z, 1, 1e-4f);
}

TEST(CrlFunctions, LotSplitsGoXFastestFromTheLowCorner) {
    std::string text = "L = rect(0, 0, 4, 6);\nL -> lot_split(1, 2) {A | B | C | D | E | F};\n";
    for (char h : std::string("ABCDEF"))
        text += std::string(1, h) + " -> add_material(\"" + char(h + 32) + "\", 1, 1, 1) {" + h + "V};\n" + h + "V -> insert_volume(1, 1, 1, 0, 0, 1);\n";
    const Grammar g = rules(text);
    auto m = byMaterial(g, deriveOnce(g));
    expectVec(m["a"].at(0).centre, 1, 0.5f, -1);
    expectVec(m["b"].at(0).centre, 3, 0.5f, -1);
    expectVec(m["c"].at(0).centre, 1, 0.5f, -3);
    expectVec(m["f"].at(0).centre, 3, 0.5f, -5);
    expectVec(m["f"].at(0).half, 1, 0.5f, 1);

    const Grammar ratios = rules("L = rect(0, 0, 8, 2);\nL -> lot_split(2, 1, 25, 75, 100) {A};\nA -> insert_volume(1, 1, 1, 0, 0, 1);");
    const Geometry r = deriveOnce(ratios);
    ASSERT_EQ(r.primitives.size(), 2u);
    expectVec(nearest(r, {1, 0.5f, -1}).half, 1, 0.5f, 1);
    expectVec(nearest(r, {5, 0.5f, -1}).half, 3, 0.5f, 1);

    const Grammar simple = rules("L = rect(0, 0, 4, 4);\nL -> lot_split_simple(0.25, 0.5) {A};\nA -> insert_volume(1, 1, 1, 0, 0, 1);");
    const Geometry s = deriveOnce(simple);
    ASSERT_EQ(s.primitives.size(), 4u);
    expectVec(nearest(s, {0.5f, 0.5f, -1}).centre, 0.5f, 0.5f, -1);
    expectVec(nearest(s, {0.5f, 0.5f, -1}).half, 0.5f, 0.5f, 1);
    expectVec(nearest(s, {2.5f, 0.5f, -3}).half, 1.5f, 0.5f, 1);

    const Grammar random = rules("L = rect(0, 0, 9, 3);\nL -> lot_split_rand(2, 1) {A};\nA -> insert_volume(1, 1, 1, 0, 0, 1);");
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Geometry rg = deriveOnce(random, seed);
        ASSERT_EQ(rg.primitives.size(), 6u);
        float area = 0;
        for (const Primitive& p : rg.primitives) {
            EXPECT_GT(p.half.x, 0.1f);
            EXPECT_GT(p.half.z, 0.1f);
            area += 4 * p.half.x * p.half.z;
        }
        EXPECT_NEAR(area, 27, 1e-3f) << "the lots tile the 9 x 3 lot";
    }
}

TEST(CrlFunctions, CompFacesStartFacingMinusYGoAnticlockwiseAndHaveUnitDepth) {
    std::string text = "L = rect(-2, -1, 2, 1);\nL -> extrude(3) {V};\nV -> comp(4) {T | F0 | F1 | F2 | F3};\n"
                       "T -> add_material(\"top\", 1, 1, 1) {TV};\nTV -> insert_volume(1, 1, 0.5, 0, 0, 1);\n";
    for (int k = 0; k < 4; ++k) {
        const std::string h = "F" + std::to_string(k);
        text += h + " -> add_material(\"f" + std::to_string(k) + "\", 1, 1, 1) {" + h + "V};\n" + h + "V -> insert_volume(1, 1, 1, 0, 0, 1);\n";
    }
    const Grammar g = rules(text);
    auto m = byMaterial(g, deriveOnce(g));
    expectVec(m["f0"].at(0).centre, 0, 1.5f, 1, "-Y face");
    expectVec(m["f1"].at(0).centre, 2, 1.5f, 0, "+X face");
    expectVec(m["f2"].at(0).centre, 0, 1.5f, -1, "+Y face");
    expectVec(m["f3"].at(0).centre, -2, 1.5f, 0, "-X face");
    expectVec(m["f0"].at(0).half, 2, 1.5f, 0.5f, "4 wide, 3 high, 1 deep");
    expectVec(m["f1"].at(0).half, 1, 1.5f, 0.5f);
    expectVec(m["top"].at(0).centre, 0, 3.75f, 0, "on top, half the volume's height");

    const Grammar hexagon = rules("L = circ(0, 0, 2);\nL -> extrude(1) {V};\nV -> comp(6) {T | F};\nT -> insert_volume(1, 1, 1, 0, 0, 0);\n"
                                  "F -> insert_volume(1, 1, 1, 0, 0, 1);");
    const Geometry h = deriveOnce(hexagon);
    ASSERT_EQ(h.primitives.size(), 6u);
    expectVec(nearest(h, {0, 0.5f, 1}).centre, 0, 0.5f, 1, "a face faces -Y, at the apothem 1");
    EXPECT_NEAR(2 * nearest(h, {0, 0.5f, 1}).half.x, 2 * std::tan(M_PI / 6), 1e-4) << "the hexagon around the circle of radius 1";
    for (const Primitive& p : h.primitives) EXPECT_NEAR(std::hypot(p.centre.x, p.centre.z), 1, 1e-4);
}

TEST(CrlFunctions, SubdivGoesUpSplitGoesAlongAndInsertedObjectsStandUpright) {
    const Grammar g = rules("L = rect(0, 0, 10, 4);\nL -> extrude(10) {V};\nV -> comp(4) {T | F};\nT -> insert_volume(1, 1, 1, 0, 0, 0);\n"
                            "F -> subdiv(70, 30) {Low | High};\nLow -> split(25, 75) {W | Blank};\nBlank -> insert_volume(1, 1, 1, 0, 0, 0);\n"
                            "High -> insert_volume(1, 1, 1, 0, 0, 0);\nW -> insert(\"data/simple_window.obj\");");
    const Geometry geo = deriveOnce(g);
    ASSERT_EQ(geo.primitives.size(), 4u);  // one window per face
    const Primitive& front = nearest(geo, {1.25f, 3.5f, 0});
    EXPECT_EQ(front.kind, PrimitiveKind::Mesh);
    expectVec(front.centre, 1.25f, 3.5f, 0, "the left quarter (seen from outside) of the lower 70 % of the -Y face");
    EXPECT_NEAR(glm::dot(front.axes[2], glm::vec3(0, 1, 0)), 1, 1e-5f) << "the OBJ's z is up";
    EXPECT_NEAR(glm::dot(front.axes[1], glm::vec3(0, 0, -1)), 1, 1e-5f) << "its -y (front) faces out of the -Y face";
    EXPECT_NEAR(front.half.z, 3.5f, 1e-4f);
    EXPECT_NEAR(front.half.y, 0.5f, 1e-4f);
}

TEST(CrlFunctions, StochasticRulesFollowTheirProbabilitiesPieceByPiece) {
    const Grammar g = rules("L = rect(0, 0, 1000, 1);\nL -> extrude(1) {V};\nV -> uniform_split(2000) {P};\n"
                            "P -> [0.3] insert_volume(1, 1, 1, 0, 0, 1), [0.7] insert_cylinder(1, 1, 1, 8);");
    const Geometry geo = deriveOnce(g);
    ASSERT_EQ(geo.primitives.size(), 2000u);
    int boxes = 0;
    for (const Primitive& p : geo.primitives) boxes += p.kind == PrimitiveKind::Box;
    EXPECT_NEAR(boxes / 2000.0, 0.3, 0.04);
}

TEST(CrlFunctions, SeveralRulesOfOnePredecessorAllApplyWithEitherArrow) {
    const Grammar g = rules("L = rect(0, 0, 2, 2);\nL -> extrude(1) {A};\nL \xE2\x86\x92 extrude(3) {B};\n"
                            "A -> insert_volume(1, 1, 1, 0, 0, 1);\nB -> insert_cylinder(1, 1, 1, 8);");
    const Geometry geo = deriveOnce(g);
    ASSERT_EQ(geo.primitives.size(), 2u);
    std::map<PrimitiveKind, float> height;
    for (const Primitive& p : geo.primitives) height[p.kind] = 2 * p.half.y;
    EXPECT_NEAR(height[PrimitiveKind::Box], 1, 1e-5f);
    EXPECT_NEAR(height[PrimitiveKind::Cylinder], 3, 1e-5f) << "the second rule runs on the lot, not on the first's result";
}

TEST(CrlFunctions, AttrsAreUsableAndOverridable) {
    const std::string text = "attr width = 4;\nattr high = 2.5;\nL = rect(0, 0, width, 1);\nL -> extrude(high) {A};\n"
                             "A -> insert_volume(1, 1, 1, 0, 0, 1);";
    expectVec(deriveOnce(rules(text)).primitives[0].half, 2, 1.25f, 0.5f);
    expectVec(deriveOnce(rules(text, {{"width", 8}})).primitives[0].half, 4, 1.25f, 0.5f);
}

TEST(CrlFunctions, RandBecomesAnEvolvableParameterWithinItsBounds) {
    const Grammar g = rules("L = rect(0, 0, 1, 1);\nL -> extrude(rand(2, 5)) {A};\nA -> insert_volume(1, 1, 1, 0, 0, 1);");
    ASSERT_EQ(g.rules[g.start].paramFloats, 1);  // one gene parameter, u in [0, 1]
    std::set<float> heights;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const float h = 2 * deriveOnce(g, seed).primitives[0].half.y;
        EXPECT_GE(h, 2.0f);
        EXPECT_LE(h, 5.0f);
        heights.insert(h);
    }
    EXPECT_GT(heights.size(), 15u);
    // the gene's value is the draw: u = 0 and u = 1 give the bounds
    Chromosome c;
    Rng rng(1);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    Geometry geo;
    DeriveScratch scratch;
    for (float u : {0.0f, 1.0f}) {
        std::memcpy(&c.words[Chromosome::paramWord(0, g.rules[c.rule(0)])], &u, sizeof u);
        derive(g, c, geo, scratch);
        EXPECT_NEAR(2 * geo.primitives[0].half.y, u == 0 ? 2 : 5, 1e-5f);
    }
}

TEST(CrlFunctions, IncludesAddTheirRulesAndInsertedRuleFilesFitTheFrame) {
    TempDir dir;
    writeFile(dir.file("parts.rule"), "attr tall = 4;\nB -> insert_volume(1, 1, 1, 0, 0, 1);\nB -> insert_cylinder(0.5, 0.5, 1, 8);\n");
    writeFile(dir.file("main.rule"), "include \"parts.rule\";\nL = rect(0, 0, 2, 2);\nL -> extrude(tall) {B};\n");
    const Grammar inc = loadGrammar(dir.file("main.rule"));
    EXPECT_EQ(inc.includes, std::vector<std::string>{"parts.rule"});
    const Geometry a = deriveOnce(inc);
    ASSERT_EQ(a.primitives.size(), 2u);
    EXPECT_NEAR(2 * a.primitives[0].half.y, 4, 1e-5f);

    writeFile(dir.file("child.rule"), "Lot = rect(0, 0, 2, 1);\nLot -> extrude(1) {V};\nV -> insert_volume(1, 1, 1, 0, 0, 1);\n");
    writeFile(dir.file("parent.rule"), "L = rect(-5, -2.5, 5, 2.5);\nL -> extrude(4) {M};\nM -> insert(\"child.rule\", 1);\n");
    const Geometry b = deriveOnce(loadGrammar(dir.file("parent.rule")));
    ASSERT_EQ(b.primitives.size(), 1u);
    expectVec(b.primitives[0].half, 5, 2, 2.5f, "the child's 2 x 1 lot fills the 10 x 5 frame, its unit height the frame's 4");
    expectVec(b.primitives[0].centre, 0, 2, 0);
}

TEST(CrlFunctions, RecursiveStochasticRulesAreOptionalChildSlotsThatEnd) {
    const Grammar g = rules("L = rect(0, 0, 1, 1);\nL -> extrude(1) {A};\n"
                            "A -> [0.7] insert_volume(1, 1, 1, 0, 0, 1) {A}, [0.3] insert_volume(1, 1, 1, 1, 1, 1);");
    bool optional = false;
    for (const Rule& r : g.rules)
        for (const Slot& s : r.slots) optional = optional || s.optional;
    EXPECT_TRUE(optional);
    std::set<std::size_t> sizes;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Geometry geo = deriveOnce(g, seed);
        sizes.insert(geo.primitives.size());
        EXPECT_EQ(geo.primitives.back().kind, PrimitiveKind::Roof) << "every stack ends with the pyramid";
        for (std::size_t k = 0; k < geo.primitives.size(); ++k) EXPECT_NEAR(geo.primitives[k].centre.y, 0.5f + float(k), 1e-4f);
    }
    EXPECT_GE(sizes.size(), 4u);
}

TEST(CrlFunctions, AChainOfHandlesDeeperThanInlineCallsMayNestStillDerives) {
    std::string text = "L = rect(0, 0, 1, 1);\nL -> extrude(1) {H0};\n";
    for (int i = 0; i < 300; ++i) text += "H" + std::to_string(i) + " -> extrude(1.01) {H" + std::to_string(i + 1) + "};\n";
    text += "H300 -> insert_volume(1, 1, 1, 0, 0, 1);\n";
    const Grammar g = rules(text);
    Chromosome c;
    Rng rng(1);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 1000));
    EXPECT_GT(c.genes, 20u) << "the chain is cut into genes of at most a dozen levels";
    Geometry geo;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    ASSERT_EQ(geo.primitives.size(), 1u);
    EXPECT_NEAR(2 * geo.primitives[0].half.y, std::pow(1.01, 300), 1e-2);
}

}  // namespace
}  // namespace shapevo
