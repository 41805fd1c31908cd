// Geometry is finite or refused: a primitive with a non-finite or absurd number (beyond
// kMaxCoordinate) stops the derivation with NonFinite, naming its rule, and never reaches the
// geometry; scorers give such a model the worst fitness and count it; the primitive limit is a
// parameter and its truncation is counted too.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../model_stream.hpp"
#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "score/volume/volume_scorer.hpp"

namespace shapevo {
namespace {

using test::rootOnly;


/// A box, then a child rule whose scale is `scale`.
Grammar withChildScale(const std::string& scale) {
    return parseGrammar("start A\nrule A {\n  box\n  child B\n}\nrule B {\n  param p = uniform(0, 1)\n  scale " + scale +
                            "\n  box\n}\n",
                        "bad.grammar");
}

TEST(NonFinite, DivisionByZeroSqrtOfANegativeAndHugeScalesStopTheDerivationNamingTheRule) {
    for (const char* scale : {"(1 / (p * 0), 1, 1)", "(1, sqrt(-1 - p * p), 1)", "(1e30, 1, 1)", "(1, 1, 3e6)"}) {
        const Grammar g = withChildScale(scale);
        Geometry out;
        DeriveScratch scratch;
        EXPECT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::NonFinite) << scale;
        EXPECT_EQ(g.rules[scratch.badRule].name, "B") << scale;
        ASSERT_EQ(out.primitives.size(), 1u) << "only A's finite box is kept";
        for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isfinite(out.primitives[0].centre[a]));
    }
}

TEST(NonFinite, ANonFiniteRotationAngleStopsTheDerivation) {
    const Grammar g = parseGrammar("start A\nrule A {\n  box\n  child B\n}\nrule B {\n  rotate y (0 / 0)\n  box\n}\n", "turn.grammar");
    Geometry out;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::NonFinite);
    EXPECT_EQ(g.rules[scratch.badRule].name, "B");
    EXPECT_EQ(out.primitives.size(), 1u);
}

TEST(NonFinite, ANearlyAbsurdScaleIsStillAModel) {
    const Grammar g = withChildScale("(1, 1, 9e5)");
    Geometry out;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, rootOnly(g), out, scratch), DeriveStatus::Complete);
    EXPECT_EQ(out.primitives.size(), 2u);
}

TEST(NonFinite, TheScorerGivesTheWorstFitnessAndCountsIt) {
    const Grammar g = withChildScale("(1 / (p * 0), 1, 1)");
    VolumeTarget target;
    target.grid.nx = target.grid.ny = target.grid.nz = 8;
    target.grid.origin = glm::dvec3(-2.0);
    target.grid.voxelSize = 0.5;
    target.fill.assign(target.grid.words(), 0);
    target.avoid = target.fill;
    const VolumeScorer scorer(g, target, FitnessSettings{});
    auto w = scorer.makeWorkspace();
    EXPECT_EQ(scorer.fitness(rootOnly(g), *w), Scorer::kWorstFitness);
    EXPECT_EQ(scorer.anomalies().nonFinite, 1u);
    EXPECT_EQ(scorer.anomalies().truncated, 0u);
}

TEST(NonFinite, ThePrimitiveLimitIsAParameterAndItsTruncationIsCounted) {
    const Grammar g = parseGrammar("start A\nrule A {\n  box\n  box\n  box\n}\n", "three.grammar");
    Geometry out;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, rootOnly(g), out, scratch, 2), DeriveStatus::Truncated);
    EXPECT_EQ(out.primitives.size(), 2u);
    EXPECT_EQ(derive(g, rootOnly(g), out, scratch, 3), DeriveStatus::Complete);
}

}  // namespace
}  // namespace shapevo
