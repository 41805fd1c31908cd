// Derivation: a chromosome always gives the same primitives, statements act as documented
// (scale multiplies, translate is local, mirror duplicates with a flipped axis, rotate turns).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::identical;


void expectNear(const glm::vec3& a, const glm::vec3& b) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-5f) << "component " << i;
}

TEST(Derive, SameChromosomeGivesBitIdenticalGeometry) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/coral.grammar"));
    Rng rng(99);
    const GenomeLimits limits{200};
    DeriveScratch s1, s2;
    for (int trial = 0; trial < 50; ++trial) {
        Chromosome c;
        while (c.genes < std::uint32_t(1 + trial * 3) && grow(g, c, rng, limits)) {
        }
        Geometry a, b;
        derive(g, c, a, s1);
        derive(g, c, b, s2);  // a different scratch: no hidden state
        Geometry again;
        derive(g, c, again, s1);  // a reused scratch: no stale state
        EXPECT_FALSE(a.primitives.empty());
        EXPECT_TRUE(identical(a, b));
        EXPECT_TRUE(identical(a, again));
    }
}

TEST(Derive, SpaceshipBodyAndMirroredWingLandWhereTheGrammarSays) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    Rng rng(1);
    Chromosome c;
    plantRoot(g, c, rng);  // S and its mandatory body B
    ASSERT_EQ(c.genes, 2u);
    const std::uint32_t body = g.rules[c.rule(0)].geneWords();
    const Rule& B = g.rules[c.rule(body)];
    for (int i = 0; i < 3; ++i) c.setParam(body, B, i, 1.0f);  // size = (1, 1, 1): the base scope
    // add a wing: W is B's second slot
    const Slot& wingSlot = B.slots[1];
    const std::uint32_t wing = appendGene(g, c, wingSlot.rules[0], body, wingSlot.firstChild, rng);
    const Rule& W = g.rules[c.rule(wing)];
    const float wingSize[4] = {0.5f, 0.4f, 0.6f, 0.25f};  // size x, y, z, then move
    for (int i = 0; i < 4; ++i) c.setParam(wing, W, i, wingSize[i]);
    Geometry geo;
    DeriveScratch scratch;
    derive(g, c, geo, scratch);
    ASSERT_EQ(geo.primitives.size(), 3u);  // body + wing + its mirror image
    // S: size (1, 0.5, 1.5) at the origin; B keeps it and moves by (1.5 + 1.5) / 2 along z.
    const Primitive& b = geo.primitives[0];
    expectNear(b.centre, {0, 0, 1.5f});
    expectNear(b.half, {0.5f, 0.25f, 0.75f});
    // W: size (0.5, 0.2, 0.9), at x = +-(1 + 0.5) / 2, z = 1.5 + 0.25 * 1.5
    bool left = false, right = false;
    for (int i = 1; i < 3; ++i) {
        const Primitive& w = geo.primitives[i];
        expectNear(w.half, {0.25f, 0.1f, 0.45f});
        EXPECT_NEAR(std::fabs(w.centre.x), 0.75f, 1e-5f);
        EXPECT_NEAR(w.centre.z, 1.875f, 1e-5f);
        left |= w.centre.x < 0;
        right |= w.centre.x > 0;
    }
    EXPECT_TRUE(left && right);
}

TEST(Derive, RotationTurnsTheScopeAboutItsOwnAxis) {
    const Grammar g = parseGrammar("start R\nrule R { size (2, 1, 1) rotate z 90 translate (1, 0, 0) box }\n", "rot.grammar");
    Rng rng(1);
    Chromosome c;
    plantRoot(g, c, rng);
    Geometry geo;
    DeriveScratch scratch;
    derive(g, c, geo, scratch);
    ASSERT_EQ(geo.primitives.size(), 1u);
    // local x now points along world y
    expectNear(geo.primitives[0].centre, {0, 1, 0});
    expectNear(geo.primitives[0].axes[0], {0, 1, 0});
}

TEST(Derive, MirrorsInsideRecursionStopAtTheCapInsteadOfRunningAway) {
    // each level mirrors the rest of the rule, children included: 2^depth copies
    const Grammar g = parseGrammar("start A\nrule A { mirror x box child A prob 0.9 }\n", "mirror.grammar");
    Rng rng(1);
    Chromosome c;
    while (c.genes < 60 && grow(g, c, rng, GenomeLimits{60})) {
    }
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch, 1000), DeriveStatus::Truncated);  // 2^60 boxes would never finish
    EXPECT_EQ(geo.primitives.size(), 1000u);
}

TEST(Derive, EmptyChromosomeGivesNoGeometry) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/spaceship.grammar"));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, Chromosome{}, geo, scratch), DeriveStatus::Complete);
    EXPECT_TRUE(geo.primitives.empty());
}

}  // namespace
}  // namespace shapevo
