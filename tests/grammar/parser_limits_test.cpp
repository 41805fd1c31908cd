// Hostile or huge grammars end in a located InputError (or parse), never in a crash: the parser,
// the expression compiler and the whole-grammar check have bounded recursion and checked counters.
#include <gtest/gtest.h>

#include <string>

#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

std::string messageOf(const std::string& text) {
    try {
        parseGrammar(text, "big.grammar");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(GrammarLimits, LongChainOfMandatoryChildrenIsCheckedWithoutDeepRecursion) {
    constexpr int kRules = 50000;
    std::string text = "start R0\n";
    for (int i = 0; i < kRules; ++i) {
        text += "rule R" + std::to_string(i) + " { box";
        if (i + 1 < kRules) text += " child R" + std::to_string(i + 1);
        text += " }\n";
    }
    const Grammar g = parseGrammar(text, "big.grammar");
    ASSERT_EQ(g.rules.size(), std::size_t(kRules));
    EXPECT_EQ(g.mandatoryGenes[0], std::uint32_t(kRules));
    EXPECT_EQ(g.mandatoryGenes[kRules - 1], 1u);
    EXPECT_EQ(g.mandatoryWords[0], 3u * (kRules - 1) + 2u);
}

TEST(GrammarLimits, LongMandatoryCycleIsReportedWithoutDeepRecursion) {
    constexpr int kRules = 50000;
    std::string text = "start R0\n";
    for (int i = 0; i < kRules; ++i)
        text += "rule R" + std::to_string(i) + " { child R" + std::to_string((i + 1) % kRules) + " }\n";
    const std::string m = messageOf(text);
    EXPECT_EQ(m.rfind("big.grammar:2:6: recursion never ends: R0 -> R1 -> ", 0), 0u) << m.substr(0, 200);
}

TEST(GrammarLimits, HugeParenthesisNestingIsAnErrorNotAStackOverflow) {
    const std::string text = "start A\nrule A { rotate x " + std::string(200000, '(') + "1" + std::string(200000, ')') + " }\n";
    EXPECT_NE(messageOf(text).find("big.grammar:2:83: expression is nested too deeply"), std::string::npos);
}

TEST(GrammarLimits, HugeUnaryMinusChainIsAnErrorNotAStackOverflow) {
    const std::string text = "start A\nrule A { rotate x " + std::string(200000, '-') + "1 }\n";
    EXPECT_NE(messageOf(text).find("expression is nested too deeply"), std::string::npos);
}

TEST(GrammarLimits, HugeSumIsAnErrorNotAStackOverflow) {
    std::string text = "start A\nrule A { rotate x 1";
    for (int i = 0; i < 200000; ++i) text += "+1";
    text += " }\n";
    EXPECT_NE(messageOf(text).find("big.grammar:2:19: expression is too long"), std::string::npos);
}

TEST(GrammarLimits, NestingJustBelowTheLimitIsAccepted) {
    const int n = kMaxExpressionNesting;
    const std::string text = "start A\nrule A { rotate x " + std::string(n, '(') + "1" + std::string(n, ')') + " }\n";
    EXPECT_NO_THROW(parseGrammar(text, "big.grammar"));
}

TEST(GrammarLimits, ChildPositionsCannotWrapTheSixteenBitCounter) {
    // 1025 slots of 64 positions would wrap a 16-bit sum back to a small number.
    std::string text = "start A\nrule A {\n";
    for (int i = 0; i < 1025; ++i) text += "  child A max 64 prob 0.5\n";
    text += "}\n";
    EXPECT_EQ(messageOf(text).rfind("big.grammar:4:3: rule A has more than 64 child positions", 0), 0u);
}

TEST(GrammarLimits, RuleIdsMustFitSixteenBits) {
    std::string text = "start R0\n";
    for (int i = 0; i <= 65535; ++i) text += "rule R" + std::to_string(i) + " { }\n";
    EXPECT_EQ(messageOf(text).rfind("big.grammar:65537:6: too many rules (at most 65535)", 0), 0u) << messageOf(text);
}

TEST(GrammarLimits, TooManyParameterValues) {
    std::string text = "start A\nrule A {\n";
    for (int i = 0; i < 86; ++i) text += "  param p" + std::to_string(i) + " = uniform((0, 0, 0), (1, 1, 1))\n";
    text += "}\n";
    // 85 vector params are 255 floats; the 86th crosses 256.
    EXPECT_EQ(messageOf(text).rfind("big.grammar:88:9: rule A has more than 256 parameter values", 0), 0u) << messageOf(text);
}

TEST(GrammarLimits, LargestFloatIsAcceptedAndNextDecadeIsNot) {
    EXPECT_NO_THROW(parseGrammar("start A\nrule A { param p = uniform(-3.4e38, 3.4e38) }\n", "big.grammar"));
    EXPECT_NE(messageOf("start A\nrule A { param p = uniform(0, 3.5e38) }\n").find("big.grammar:2:31: number '3.5e38' is out of range"),
              std::string::npos);
}

TEST(GrammarLimits, ProbAndMaxMayStillNameRules) {
    // 'prob' and 'max' are only keywords after a slot's rule names.
    const Grammar g = parseGrammar("start A\nrule A { child prob prob 0.5 child max }\nrule prob { }\nrule max { }\n", "big.grammar");
    EXPECT_EQ(g.rules[0].slots[0].rules[0], 1);
    EXPECT_FLOAT_EQ(g.rules[0].slots[0].probability, 0.5f);
    EXPECT_EQ(g.rules[0].slots[1].rules[0], 2);
}

}  // namespace
}  // namespace shapevo
