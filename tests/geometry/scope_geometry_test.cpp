// scope.origin and scope.axis.x / .y / .z read the current scope's world frame: exactly the
// centre and axes of the box derive makes on that scope, after translate / rotate / mirror, in
// split and repeat pieces, comp faces, lots, child genes, and in a Pieces statement's own numbers
// (whose ScopeFrame the compiler inserts before it once its successors are compiled).
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace scope_geometry_test {

Geometry derived(const std::string& text) {
    const Grammar g = parseGrammar(text, "scope.grammar");
    Chromosome c;
    Rng rng(5);
    EXPECT_TRUE(growUncontrolled(g, c, rng, 200));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    return geo;
}

/// `text` with every BOX replaced by a box whose size is `what` + 10 (so a box's size says what
/// the expression read on its scope, exactly: 2 * half is |size| and size = value + 10 > 0), and
/// every PROBE by that box as a successor block.
std::string probing(std::string text, const std::string& what) {
    const std::string box = "size (" + what + ".x + 10, " + what + ".y + 10, " + what + ".z + 10) box";
    for (std::size_t at; (at = text.find("PROBE")) != std::string::npos;) text.replace(at, 5, "{ " + box + " }");
    for (std::size_t at; (at = text.find("BOX")) != std::string::npos;) text.replace(at, 3, box);
    return text;
}

/// Every box of `text` (PROBE: scope.origin, then each axis) read its own centre and axes, bit for bit.
void expectEveryBoxReadsItsFrame(const std::string& text, std::size_t boxes) {
    const char* what[4] = {"scope.origin", "scope.axis.x", "scope.axis.y", "scope.axis.z"};
    for (int w = 0; w < 4; ++w) {
        SCOPED_TRACE(what[w]);
        const Geometry geo = derived(probing(text, what[w]));
        ASSERT_EQ(geo.primitives.size(), boxes);
        for (const Primitive& p : geo.primitives) {
            const glm::vec3 read = w == 0 ? p.centre : p.axes[w - 1];
            for (int k = 0; k < 3; ++k) EXPECT_EQ(2.0f * p.half[k], read[k] + 10.0f) << "component " << k;
        }
    }
}

TEST(ScopeGeometry, OriginAndAxesAreTheBoxsCentreAndAxesAfterTranslateRotateAndMirror) {
    expectEveryBoxReadsItsFrame("start A\nrule A {\n  translate (1, 2, 3) rotate y 30 rotate x 20 translate (0.5, -1, 2)\n"
                                "  [ BOX ]\n  mirror x\n  translate (2, 0, 0) rotate z 15\n  [ BOX ]\n}\n",
                                3);
}

TEST(ScopeGeometry, PiecesFacesAndLotsReadTheirOwnFrames) {
    expectEveryBoxReadsItsFrame("start A\nrule A {\n  size (6, 4, 2) translate (1, 2, 3) rotate y 40\n"
                                "  repeat x count 3 PROBE\n"
                                "  split y { 1: PROBE | ~1: { rotate x 10 BOX } }\n"
                                "  comp { side: PROBE | top: { translate (0.5, 0, 0) BOX } }\n"
                                "  lot rect (-1, -1, 2, 1) { extrude 2 BOX }\n}\n",
                                3 + 2 + 5 + 1);
}

TEST(ScopeGeometry, AChildGeneReadsTheScopeItWasDerivedOn) {
    expectEveryBoxReadsItsFrame("start A\nrule A {\n  translate (3, 0, 1) rotate z 60\n  child B\n  rotate y 30\n  child B\n}\n"
                                "rule B { translate (0, 1, 0) BOX }\n",
                                2);
}

TEST(ScopeGeometry, APiecesStatementsOwnNumbersReadTheScopeItSplits) {
    // split sizes and a repeat count from scope.origin; the successors read it too, and an if / else
    // inside a piece still jumps right after the ScopeFrame is inserted before the split.
    const std::string text = "start A\nrule A {\n  size (10, 1, 1) translate (2, 0, 0)\n"
                             "  split x { scope.origin.x: { if (1) PROBE else { sphere } } | ~1: PROBE }\n"
                             "  repeat y count scope.origin.x + 1 PROBE\n}\n";
    expectEveryBoxReadsItsFrame(text, 2 + 3);
    const Geometry geo = derived(probing(text, "scope.origin"));
    int first = 0;
    for (const Primitive& p : geo.primitives) first += p.centre.x == 2.0f - 5.0f + 1.0f;
    EXPECT_EQ(first, 1) << "the first piece is scope.origin.x = 2 long";
}

TEST(ScopeGeometry, TheNormalOfAFlatScopeIsItsZAxis) {
    // comp's top face of an unrotated box looks up: dot(normal, +y) = 1; its sides are level.
    const Geometry geo = derived("start A\nrule A {\n  comp { top: { size (dot(scope.axis.z, (0, 1, 0)) + 1, 1, 1) box }"
                                 " | side: { size (dot(scope.axis.z, (0, 1, 0)) + 1, 1, 1) box } }\n}\n");
    ASSERT_EQ(geo.primitives.size(), 5u);
    int up = 0;
    for (const Primitive& p : geo.primitives) up += 2.0f * p.half.x == 2.0f;
    EXPECT_EQ(up, 1);
}

TEST(ScopeGeometry, AGrammarThatReadsNoneHasNoScopeFrameStatement) {
    const Grammar g = parseGrammar("start A\nrule A { size (2, 1, 1) split x { 1: { box } | ~1: { rotate x scope.size.x box } } }\n", "t.grammar");
    for (const Statement& st : g.rules[0].statements) EXPECT_NE(st.kind, StatementKind::ScopeFrame);
    const Grammar h = parseGrammar("start A\nrule A { box rotate x scope.origin.x box }\n", "t.grammar");
    int frames = 0;
    for (const Statement& st : h.rules[0].statements) frames += st.kind == StatementKind::ScopeFrame;
    EXPECT_EQ(frames, 1) << "one, right before the statement that reads it";
}

}  // namespace scope_geometry_test
}  // namespace shapevo
