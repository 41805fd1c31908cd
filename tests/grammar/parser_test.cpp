// The parser turns the shipped grammars (and small hand-written ones) into exactly the generator
// graph they describe: rules, params with priors, child slots with offsets and edges, gene sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "grammar/front_ends.hpp"
#include "grammar_test_util.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

using test::paramNamed;
using test::ruleNamed;
using test::shippedGrammarPath;

std::vector<std::string> ruleNames(const Grammar& g) {
    std::vector<std::string> names;
    for (const Rule& r : g.rules) names.push_back(r.name);
    return names;
}

std::vector<StatementKind> statementKinds(const Rule& r) {
    std::vector<StatementKind> kinds;
    for (const Statement& s : r.statements) kinds.push_back(s.kind);
    return kinds;
}

// ---------------------------------------------------------------------------------------------
// grammars/spaceship.grammar

class GrammarSpaceship : public ::testing::Test {
protected:
    static void SetUpTestSuite() { g_ = new Grammar(loadGrammar(shippedGrammarPath("spaceship.grammar"))); }
    static void TearDownTestSuite() {
        delete g_;
        g_ = nullptr;
    }
    static Grammar* g_;
};
Grammar* GrammarSpaceship::g_ = nullptr;

TEST_F(GrammarSpaceship, HasRulesInFileOrderAndStartsAtS) {
    const Grammar& g = *g_;
    EXPECT_EQ(ruleNames(g), (std::vector<std::string>{"S", "B", "W", "w", "T", "t"}));
    EXPECT_EQ(g.rules[g.start].name, "S");
    EXPECT_EQ(g.path, shippedGrammarPath("spaceship.grammar"));
    EXPECT_NE(g.source.find("rule B {"), std::string::npos) << "the full source text is kept";
}

TEST_F(GrammarSpaceship, RuleNamesAreCaseSensitive) {
    EXPECT_NE(g_->findRule("W"), g_->findRule("w"));
    EXPECT_NE(g_->findRule("T"), g_->findRule("t"));
    EXPECT_EQ(g_->findRule("X"), -1);
}

TEST_F(GrammarSpaceship, RuleLocationsPointAtTheRuleName) {
    const Rule& s = ruleNamed(*g_, "S");
    EXPECT_EQ(s.where.line, 9);
    EXPECT_EQ(s.where.column, 6);
}

TEST_F(GrammarSpaceship, BodySizeIsAUniformVectorParam) {
    const Rule& b = ruleNamed(*g_, "B");
    ASSERT_EQ(b.params.size(), 1u);
    const Param& size = paramNamed(b, "size");
    EXPECT_EQ(size.dims, 3);
    EXPECT_EQ(size.first, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(size.prior[c].kind, PriorKind::Uniform);
        EXPECT_FLOAT_EQ(size.prior[c].lo, 0.6f);
        EXPECT_FLOAT_EQ(size.prior[c].hi, 1.5f);
    }
    EXPECT_EQ(b.paramFloats, 3);
}

TEST_F(GrammarSpaceship, WingParamsHavePerComponentBoundsAndFollowEachOther) {
    const Rule& w = ruleNamed(*g_, "W");
    ASSERT_EQ(w.params.size(), 2u);
    const Param& size = paramNamed(w, "size");
    const Param& move = paramNamed(w, "move");
    EXPECT_EQ(size.dims, 3);
    EXPECT_EQ(size.first, 0);
    EXPECT_EQ(move.dims, 1);
    EXPECT_EQ(move.first, 3);
    const float lo[3] = {0.3f, 0.2f, 0.2f}, hi[3] = {1.2f, 0.5f, 1.0f};
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(size.prior[c].lo, lo[c]) << c;
        EXPECT_FLOAT_EQ(size.prior[c].hi, hi[c]) << c;
    }
    EXPECT_EQ(move.prior[0].kind, PriorKind::Uniform);
    EXPECT_FLOAT_EQ(move.prior[0].lo, -0.5f);
    EXPECT_FLOAT_EQ(move.prior[0].hi, 0.5f);
    EXPECT_EQ(w.paramFloats, 4);
}

TEST_F(GrammarSpaceship, SlotsHaveProbabilitiesOffsetsAndTargets) {
    const Grammar& g = *g_;
    const Rule& s = ruleNamed(g, "S");
    ASSERT_EQ(s.slots.size(), 1u);
    EXPECT_TRUE(s.slots[0].mandatory());
    EXPECT_EQ(s.slots[0].rules, (std::vector<std::uint16_t>{std::uint16_t(g.findRule("B"))}));

    const Rule& b = ruleNamed(g, "B");
    ASSERT_EQ(b.slots.size(), 3u);
    const char* targets[3] = {"B", "W", "T"};
    const float probs[3] = {0.6f, 0.5f, 0.5f};
    for (std::size_t i = 0; i < 3; ++i) {
        const Slot& slot = b.slots[i];
        ASSERT_EQ(slot.rules.size(), 1u);
        EXPECT_EQ(g.rules[slot.rules[0]].name, targets[i]);
        EXPECT_EQ(slot.weights, (std::vector<float>{1.0f}));
        EXPECT_FLOAT_EQ(slot.probability, probs[i]);
        EXPECT_FALSE(slot.mandatory());
        EXPECT_EQ(slot.maxCount, 1);
        EXPECT_EQ(slot.firstChild, i);
    }
    EXPECT_EQ(b.childOffsets, 3);
}

TEST_F(GrammarSpaceship, EdgesAreNumberedInSourceOrderAndUnique) {
    const Grammar& g = *g_;
    std::vector<std::uint32_t> edges;
    for (const Rule& r : g.rules)
        for (const Slot& s : r.slots) edges.push_back(s.edge);
    EXPECT_EQ(edges, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(g.edgeCount, 8u);
}

TEST_F(GrammarSpaceship, GeneWordsAreHeaderPlusChildOffsetsPlusParams) {
    const Grammar& g = *g_;
    EXPECT_EQ(ruleNamed(g, "S").geneWords(), 2u + 1u + 0u);
    EXPECT_EQ(ruleNamed(g, "B").geneWords(), 2u + 3u + 3u);
    EXPECT_EQ(ruleNamed(g, "W").geneWords(), 2u + 1u + 4u);
    EXPECT_EQ(ruleNamed(g, "w").geneWords(), 2u + 1u + 4u);
    EXPECT_EQ(ruleNamed(g, "T").geneWords(), 2u + 1u + 3u);
    EXPECT_EQ(ruleNamed(g, "t").geneWords(), 2u + 1u + 3u);
}

TEST_F(GrammarSpaceship, StartAlwaysBringsOneBody) {
    const Grammar& g = *g_;
    ASSERT_EQ(g.mandatoryGenes.size(), g.rules.size());
    EXPECT_EQ(g.mandatoryGenes[g.findRule("S")], 2u);
    EXPECT_EQ(g.mandatoryWords[g.findRule("S")], 3u + 8u);
    for (const char* name : {"B", "W", "w", "T", "t"}) {
        EXPECT_EQ(g.mandatoryGenes[g.findRule(name)], 1u) << name;
        EXPECT_EQ(g.mandatoryWords[g.findRule(name)], ruleNamed(g, name).geneWords()) << name;
    }
}

TEST_F(GrammarSpaceship, StatementsKeepSourceOrder) {
    using K = StatementKind;
    const Grammar& g = *g_;
    EXPECT_EQ(statementKinds(ruleNamed(g, "S")), (std::vector<K>{K::Size, K::Child}));
    EXPECT_EQ(statementKinds(ruleNamed(g, "B")),
              (std::vector<K>{K::Scale, K::Translate, K::Primitive, K::Child, K::Child, K::Child}));
    const Rule& w = ruleNamed(g, "W");
    EXPECT_EQ(statementKinds(w), (std::vector<K>{K::Mirror, K::Scale, K::Translate, K::Primitive, K::Child}));
    EXPECT_EQ(w.statements[0].axis, 0) << "mirror x";
    EXPECT_EQ(w.statements[3].primitive, PrimitiveKind::Box);
    EXPECT_EQ(w.statements[4].slot, 0);
    const Rule& b = ruleNamed(g, "B");
    EXPECT_EQ(b.statements[3].slot, 0);
    EXPECT_EQ(b.statements[4].slot, 1);
    EXPECT_EQ(b.statements[5].slot, 2);
}

TEST_F(GrammarSpaceship, ExpressionStackFitsTheEvaluator) {
    EXPECT_GE(g_->maxStack, 2);
    EXPECT_LE(g_->maxStack, 32);
}

// ---------------------------------------------------------------------------------------------
// grammars/coral.grammar

class GrammarCoral : public ::testing::Test {
protected:
    static void SetUpTestSuite() { g_ = new Grammar(loadGrammar(shippedGrammarPath("coral.grammar"))); }
    static void TearDownTestSuite() {
        delete g_;
        g_ = nullptr;
    }
    static Grammar* g_;
};
Grammar* GrammarCoral::g_ = nullptr;

TEST_F(GrammarCoral, HasRulesAndStartsAtRoot) {
    EXPECT_EQ(ruleNames(*g_), (std::vector<std::string>{"Root", "Stem", "Bud", "Cap"}));
    EXPECT_EQ(g_->rules[g_->start].name, "Root");
}

TEST_F(GrammarCoral, StemHasNormalUniformAndIntPriors) {
    const Rule& stem = ruleNamed(*g_, "Stem");
    ASSERT_EQ(stem.params.size(), 3u);
    const Param& len = paramNamed(stem, "len");
    EXPECT_EQ(len.dims, 1);
    EXPECT_EQ(len.first, 0);
    EXPECT_EQ(len.prior[0].kind, PriorKind::Normal);
    EXPECT_FLOAT_EQ(len.prior[0].mu, 1.2f);
    EXPECT_FLOAT_EQ(len.prior[0].sigma, 0.4f);
    EXPECT_FLOAT_EQ(len.prior[0].lo, 0.4f);
    EXPECT_FLOAT_EQ(len.prior[0].hi, 2.0f);

    const Param& turn = paramNamed(stem, "turn");
    EXPECT_EQ(turn.first, 1);
    EXPECT_EQ(turn.prior[0].kind, PriorKind::Uniform);
    EXPECT_FLOAT_EQ(turn.prior[0].lo, 0.0f);
    EXPECT_FLOAT_EQ(turn.prior[0].hi, 360.0f);

    const Param& tilt = paramNamed(stem, "tilt");
    EXPECT_EQ(tilt.first, 2);
    EXPECT_EQ(tilt.prior[0].kind, PriorKind::Int);
    EXPECT_FLOAT_EQ(tilt.prior[0].lo, 5.0f);
    EXPECT_FLOAT_EQ(tilt.prior[0].hi, 60.0f);
    EXPECT_EQ(stem.paramFloats, 3);
}

TEST_F(GrammarCoral, BudHasChoiceAndSignedVectorUniform) {
    const Grammar& g = *g_;
    const Rule& bud = ruleNamed(g, "Bud");
    const Param& kind = paramNamed(bud, "kind");
    EXPECT_EQ(kind.dims, 1);
    EXPECT_EQ(kind.prior[0].kind, PriorKind::Choice);
    ASSERT_EQ(kind.prior[0].choiceCount, 3u);
    const std::vector<float> values(g.choiceValues.begin() + kind.prior[0].choiceBegin,
                                    g.choiceValues.begin() + kind.prior[0].choiceBegin + 3);
    EXPECT_EQ(values, (std::vector<float>{0.5f, 1.0f, 1.5f}));
    EXPECT_FLOAT_EQ(kind.prior[0].lo, 0.5f) << "a choice's support spans its values";
    EXPECT_FLOAT_EQ(kind.prior[0].hi, 1.5f);

    const Param& lean = paramNamed(bud, "lean");
    EXPECT_EQ(lean.dims, 3);
    EXPECT_EQ(lean.first, 1);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(lean.prior[c].lo, -20.0f);
        EXPECT_FLOAT_EQ(lean.prior[c].hi, 20.0f);
    }
    EXPECT_EQ(bud.paramFloats, 4);
}

TEST_F(GrammarCoral, RootHasTwoStemSlotsWithTwoSiblingsEach) {
    const Grammar& g = *g_;
    const Rule& root = ruleNamed(g, "Root");
    ASSERT_EQ(root.slots.size(), 2u);
    const std::uint16_t stem = std::uint16_t(g.findRule("Stem"));
    EXPECT_EQ(root.slots[0].rules, (std::vector<std::uint16_t>{stem}));
    EXPECT_TRUE(root.slots[0].mandatory());
    EXPECT_EQ(root.slots[0].maxCount, 2);
    EXPECT_EQ(root.slots[0].firstChild, 0);
    EXPECT_EQ(root.slots[1].rules, (std::vector<std::uint16_t>{stem}));
    EXPECT_FLOAT_EQ(root.slots[1].probability, 0.5f);
    EXPECT_EQ(root.slots[1].maxCount, 2);
    EXPECT_EQ(root.slots[1].firstChild, 2) << "one child offset per sibling position";
    EXPECT_EQ(root.childOffsets, 4);
}

TEST_F(GrammarCoral, StemSlotHasWeightedAlternatives) {
    const Grammar& g = *g_;
    const Rule& stem = ruleNamed(g, "Stem");
    ASSERT_EQ(stem.slots.size(), 2u);
    const Slot& branch = stem.slots[0];
    EXPECT_EQ(branch.rules, (std::vector<std::uint16_t>{std::uint16_t(g.findRule("Stem")), std::uint16_t(g.findRule("Bud"))}));
    EXPECT_EQ(branch.weights, (std::vector<float>{3.0f, 1.0f}));
    EXPECT_FLOAT_EQ(branch.probability, 0.4f);
    EXPECT_EQ(branch.maxCount, 3);
    EXPECT_EQ(branch.firstChild, 0);
    const Slot& cap = stem.slots[1];
    EXPECT_EQ(cap.rules, (std::vector<std::uint16_t>{std::uint16_t(g.findRule("Cap"))}));
    EXPECT_FLOAT_EQ(cap.probability, 0.25f);
    EXPECT_EQ(cap.maxCount, 1);
    EXPECT_EQ(cap.firstChild, 3);
    EXPECT_EQ(stem.childOffsets, 4);
}

TEST_F(GrammarCoral, EdgeIdsAreUniqueAndDense) {
    std::set<std::uint32_t> edges;
    std::size_t slots = 0;
    for (const Rule& r : g_->rules)
        for (const Slot& s : r.slots) {
            edges.insert(s.edge);
            ++slots;
        }
    EXPECT_EQ(edges.size(), slots);
    EXPECT_EQ(g_->edgeCount, 4u);
    EXPECT_EQ(*edges.rbegin(), 3u);
}

TEST_F(GrammarCoral, GeneWords) {
    const Grammar& g = *g_;
    EXPECT_EQ(ruleNamed(g, "Root").geneWords(), 2u + 4u + 0u);
    EXPECT_EQ(ruleNamed(g, "Stem").geneWords(), 2u + 4u + 3u);
    EXPECT_EQ(ruleNamed(g, "Bud").geneWords(), 2u + 0u + 4u);
    EXPECT_EQ(ruleNamed(g, "Cap").geneWords(), 2u + 0u + 1u);
}

TEST_F(GrammarCoral, RootAlwaysBringsTwoStemsSoThreeGenes) {
    const Grammar& g = *g_;
    EXPECT_EQ(g.mandatoryGenes[g.findRule("Root")], 3u);
    EXPECT_EQ(g.mandatoryWords[g.findRule("Root")], 6u + 2u * 9u);
    EXPECT_EQ(g.mandatoryGenes[g.findRule("Stem")], 1u) << "Stem's slots all have prob < 1";
    EXPECT_EQ(g.mandatoryGenes[g.findRule("Bud")], 1u);
    EXPECT_EQ(g.mandatoryGenes[g.findRule("Cap")], 1u);
}

TEST_F(GrammarCoral, RotationsNameTheirAxes) {
    const Rule& stem = ruleNamed(*g_, "Stem");
    ASSERT_GE(stem.statements.size(), 2u);
    EXPECT_EQ(stem.statements[0].kind, StatementKind::Rotate);
    EXPECT_EQ(stem.statements[0].axis, 1) << "rotate y";
    EXPECT_EQ(stem.statements[1].kind, StatementKind::Rotate);
    EXPECT_EQ(stem.statements[1].axis, 0) << "rotate x";
    const Rule& bud = ruleNamed(*g_, "Bud");
    EXPECT_EQ(bud.statements[0].kind, StatementKind::Rotate);
    EXPECT_EQ(bud.statements[0].axis, 2) << "rotate z";
}

// ---------------------------------------------------------------------------------------------
// Small grammars: the parts of the language the shipped grammars do not show.

TEST(GrammarParser, MandatoryGenesTakeTheLargestAlternativeTimesMaxCount) {
    const Grammar g = parseGrammar(
        "start A\n"
        "rule A { child [1] Small | [2] Big max 3 }\n"
        "rule Small { box }\n"
        "rule Big { child Leaf max 2 child Leaf prob 0.1 }\n"
        "rule Leaf { box }\n",
        "t.grammar");
    EXPECT_EQ(g.mandatoryGenes[g.findRule("Big")], 3u);
    EXPECT_EQ(g.mandatoryGenes[g.findRule("A")], 1u + 3u * 3u);
    const std::uint32_t bigWords = 2u + 3u + 2u * 2u;  // Big gene + two Leaf genes
    EXPECT_EQ(g.mandatoryWords[g.findRule("A")], (2u + 3u) + 3u * bigWords);
}

TEST(GrammarParser, ProbabilityZeroAndOneAndSixtyFourChildPositionsAreAccepted) {
    const Grammar g = parseGrammar("start A\nrule A { child B prob 0 child B max 63 prob 1 }\nrule B { }\n", "t.grammar");
    const Rule& a = g.rules[0];
    ASSERT_EQ(a.slots.size(), 2u);
    EXPECT_FLOAT_EQ(a.slots[0].probability, 0.0f);
    EXPECT_EQ(a.slots[1].maxCount, 63);
    EXPECT_EQ(a.slots[1].firstChild, 1);
    EXPECT_EQ(a.childOffsets, 64) << "slot 0 has one position, slot 1 has 63: exactly the limit";
    EXPECT_EQ(g.mandatoryGenes[0], 64u);
    EXPECT_NO_THROW(parseGrammar("start A\nrule A { child A max 64 prob 0.5 }\n", "t.grammar"));
}

TEST(GrammarParser, RecursionThroughAProbabilityBelowOneIsFine) {
    const Grammar g = parseGrammar("start A\nrule A { child B }\nrule B { child A prob 0.99 }\n", "t.grammar");
    EXPECT_EQ(g.mandatoryGenes[0], 2u);
    EXPECT_EQ(g.mandatoryGenes[1], 1u);
}

TEST(GrammarParser, RulesMayBeUsedBeforeTheyAreDefinedAndStartMayComeLast) {
    const Grammar g = parseGrammar("rule A { child B }\nrule B { box }\nstart A\n", "t.grammar");
    EXPECT_EQ(g.start, 0);
    EXPECT_EQ(g.rules[0].slots[0].rules[0], 1);
}

TEST(GrammarParser, NormalPriorAcceptsVectorFormsAndBroadcastsScalars) {
    const Grammar g = parseGrammar(
        "start A\nrule A {\n"
        "  param n = normal((1, 2, 3), 0.5) in [0, (2, 4, 6)]\n"
        "  param u = uniform(-1, (1, 2, 3))\n"
        "}\n",
        "t.grammar");
    const Param& n = g.rules[0].params[0];
    EXPECT_EQ(n.dims, 3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(n.prior[c].kind, PriorKind::Normal);
        EXPECT_FLOAT_EQ(n.prior[c].mu, float(c + 1));
        EXPECT_FLOAT_EQ(n.prior[c].sigma, 0.5f);
        EXPECT_FLOAT_EQ(n.prior[c].lo, 0.0f);
        EXPECT_FLOAT_EQ(n.prior[c].hi, float(2 * (c + 1)));
    }
    const Param& u = g.rules[0].params[1];
    EXPECT_EQ(u.dims, 3);
    EXPECT_EQ(u.first, 3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(u.prior[c].lo, -1.0f);
        EXPECT_FLOAT_EQ(u.prior[c].hi, float(c + 1));
    }
}

TEST(GrammarParser, PriorArgumentsMayUseAttrsPiAndNegation) {
    const Grammar g = parseGrammar(
        "attr half = 0.5\nstart A\nrule A {\n"
        "  param a = uniform(-pi, pi)\n"
        "  param b = choice(half, -half, 2)\n"
        "  child [half] A | [1] B prob half\n"
        "}\nrule B { }\n",
        "t.grammar");
    const Rule& a = g.rules[0];
    EXPECT_FLOAT_EQ(a.params[0].prior[0].lo, -float(M_PI));
    EXPECT_FLOAT_EQ(a.params[0].prior[0].hi, float(M_PI));
    const Prior& b = a.params[1].prior[0];
    EXPECT_EQ(std::vector<float>(g.choiceValues.begin() + b.choiceBegin, g.choiceValues.begin() + b.choiceBegin + b.choiceCount),
              (std::vector<float>{0.5f, -0.5f, 2.0f}));
    EXPECT_EQ(a.slots[0].weights, (std::vector<float>{0.5f, 1.0f}));
    EXPECT_FLOAT_EQ(a.slots[0].probability, 0.5f);
}

TEST(GrammarParser, IntPriorMayHaveFractionalBoundsAroundAWholeNumber) {
    const Grammar g = parseGrammar("start A\nrule A { param n = int(0.5, 1.5) }\n", "t.grammar");
    EXPECT_EQ(g.rules[0].params[0].prior[0].kind, PriorKind::Int);
}

TEST(GrammarParser, CommentsAndBlankLinesAreIgnored) {
    const Grammar g = parseGrammar("# header\n\n start A # trailing\nrule A{box}# end", "t.grammar");
    ASSERT_EQ(g.rules.size(), 1u);
    EXPECT_EQ(g.rules[0].statements.size(), 1u);
}

TEST(GrammarParser, ChoiceValuesOfDifferentParamsAreKeptApart) {
    const Grammar g = parseGrammar(
        "start A\nrule A { param a = choice(1, 2) }\nrule B { param b = choice(3, 4, 5) }\n", "t.grammar");
    const Prior& a = g.rules[0].params[0].prior[0];
    const Prior& b = g.rules[1].params[0].prior[0];
    EXPECT_EQ(a.choiceBegin, 0u);
    EXPECT_EQ(a.choiceCount, 2u);
    EXPECT_EQ(b.choiceBegin, 2u);
    EXPECT_EQ(b.choiceCount, 3u);
    EXPECT_EQ(g.choiceValues, (std::vector<float>{1, 2, 3, 4, 5}));
}

TEST(GrammarParser, ParamsAreVisibleOnlyInTheirOwnRule) {
    EXPECT_NO_THROW(parseGrammar("start A\nrule A { param p = uniform(0, 1) rotate x p }\n", "t.grammar"));
    EXPECT_THROW(parseGrammar("start A\nrule A { param p = uniform(0, 1) child B }\nrule B { rotate x p }\n", "t.grammar"),
                 InputError);
}

}  // namespace
}  // namespace shapevo
