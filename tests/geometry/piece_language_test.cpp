// The .grammar statements CastleMaker's front end needs, on their own: `[ ]` runs on a copy of
// the scope; `per piece` parameters give each piece of a kind its own value (the first the gene's
// own); an `optional` slot lets a recursion through probability-1 slots end (and a fresh gene
// does not bring it); atan2; a successor named twice in one statement is compiled once.
#include <gtest/gtest.h>

#include <set>

#include "base/input_error.hpp"
#include "genome/operators.hpp"
#include "genome/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

Geometry deriveSample(const Grammar& g, std::uint64_t seed = 1) {
    Chromosome c;
    Rng rng(seed);
    EXPECT_TRUE(growUncontrolled(g, c, rng, 200));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    return geo;
}

TEST(PieceLanguage, ABracketBlockRunsOnACopyOfTheScope) {
    const Geometry geo = deriveSample(parseGrammar("start A\nrule A { [ translate (5, 0, 0) scale 2 box ] box }", "t.grammar"));
    ASSERT_EQ(geo.primitives.size(), 2u);
    std::set<float> xs;
    for (const Primitive& p : geo.primitives) xs.insert(p.centre.x + p.half.x);
    EXPECT_EQ(xs, (std::set<float>{0.5f, 6.0f})) << "the block's scale and move stay in it";
}

TEST(PieceLanguage, PerPieceParametersDrawOnePerPieceAndTheFirstIsTheGenesOwn) {
    const Grammar g = parseGrammar("start A\nrule A { size (10, 1, 1) repeat x count 10 S }\n"
                                   "rule S { param h = uniform(1, 3) per piece size (1, h, 1) box }", "t.grammar");
    const Geometry geo = deriveSample(g);
    std::set<float> heights;
    for (const Primitive& p : geo.primitives) {
        EXPECT_GE(2 * p.half.y, 1.0f);
        EXPECT_LE(2 * p.half.y, 3.0f);
        heights.insert(p.half.y);
    }
    EXPECT_EQ(heights.size(), 10u);
    Chromosome c;
    Rng rng(1);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    const float u = c.param(0, g.rules[c.rule(0)], 0);
    float first = 0;
    for (const Primitive& p : geo.primitives)
        if (p.centre.x < -4) first = 2 * p.half.y;
    EXPECT_FLOAT_EQ(first, 1 + u * 2) << "the first piece reads the gene's u itself";
}

TEST(PieceLanguage, AnOptionalSlotLetsAProbabilityOneRecursionEnd) {
    const std::string text = "start A\nrule A { box child [1] B | [1] C }\nrule B { translate (0, 1, 0) A }\nrule C { sphere }\n";
    EXPECT_THROW(parseGrammar(text, "t.grammar"), InputError) << "without optional: recursion never ends";
    const Grammar g = parseGrammar(text.substr(0, text.find("}\n")) + " optional }\n" + text.substr(text.find("}\n") + 2), "t.grammar");
    std::set<std::uint32_t> genes;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(g, c, rng, 1000));
        genes.insert(c.genes);
    }
    EXPECT_GE(genes.size(), 3u);
    EXPECT_EQ(g.mandatoryGenes[g.start], 1u) << "a fresh gene does not bring an optional child";
}

TEST(PieceLanguage, Atan2GivesTheAngleInRadians) {
    const Geometry geo = deriveSample(parseGrammar("start A\nrule A { size (atan2(1, 1) * 4, atan2(1, -1), 1) box }", "t.grammar"));
    EXPECT_NEAR(2 * geo.primitives[0].half.x, float(M_PI), 1e-5f);
    EXPECT_NEAR(2 * geo.primitives[0].half.y, float(0.75 * M_PI), 1e-5f);
}

TEST(PieceLanguage, ASuccessorNamedTwiceInOneStatementIsCompiledOnce) {
    const Grammar once = parseGrammar("start A\nrule A { size (4, 1, 1) split x { '0.5: B | '0.5: B } }\n"
                                      "rule B { param h = uniform(1, 2) box }", "t.grammar");
    EXPECT_EQ(once.rules[once.start].paramFloats, 1) << "both pieces share B's parameter";
    const Grammar twice = parseGrammar("start A\nrule A { size (4, 1, 1) split x { '0.5: B | '0.5: { B } } }\n"
                                       "rule B { param h = uniform(1, 2) box }", "t.grammar");
    EXPECT_EQ(twice.rules[twice.start].paramFloats, 2) << "a block is its own successor";
}

}  // namespace
}  // namespace shapevo
