// Compiled expressions evaluate to what the text says: operators and precedence, unary minus,
// scalar-to-vector broadcasting, swizzles, functions, attrs and pi, parameters, scope and parent.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "../test_support.hpp"
#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

// Every expression below is compiled inside this rule, so it can use p (scalar, float 0) and
// v (vector, floats 1..3) and the attr k = 2.
std::string ruleAround(const std::string& statement) {
    return "attr k = 2\nstart A\nrule A {\n"
           "  param p = uniform(0, 10)\n"
           "  param v = uniform((0, 0, 0), (10, 10, 10))\n"
           "  " + statement + "\n}\n";
}

struct Inputs {
    std::array<float, 4> params{1.5f, 4.0f, 5.0f, 6.0f};  // p = 1.5, v = (4, 5, 6)
    std::array<float, 3> scope{2.0f, 4.0f, 6.0f};
    std::array<float, 3> parent{1.0f, 2.0f, 3.0f};
};

float evalScalar(const std::string& expr, const Inputs& in = {}) {
    const Grammar g = parseGrammar(ruleAround("rotate x " + expr), "expr.grammar");
    const Statement& s = g.rules[0].statements.at(0);
    EXPECT_EQ(s.kind, StatementKind::Rotate);
    float stack[kMaxExpressionStack];
    return evaluate(g, s.expr[0], in.params.data(), in.scope.data(), in.parent.data(), stack);
}

std::array<float, 3> evalVector(const std::string& expr, const Inputs& in = {}) {
    const Grammar g = parseGrammar(ruleAround("translate " + expr), "expr.grammar");
    const Statement& s = g.rules[0].statements.at(0);
    EXPECT_EQ(s.kind, StatementKind::Translate);
    float stack[kMaxExpressionStack];
    std::array<float, 3> out{};
    for (int c = 0; c < 3; ++c) out[c] = evaluate(g, s.expr[c], in.params.data(), in.scope.data(), in.parent.data(), stack);
    return out;
}

using V = std::array<float, 3>;

TEST(GrammarExpression, ParentAndScopeSizesCombine) {
    EXPECT_FLOAT_EQ(evalScalar("(parent.size.z + scope.size.z) * 0.5"), (3.0f + 6.0f) * 0.5f);
    EXPECT_EQ(evalVector("(0, (parent.size.y + scope.size.y) * 0.5, 0)"), (V{0.0f, 3.0f, 0.0f}));
    EXPECT_EQ(evalVector("scope.size"), (V{2, 4, 6}));
    EXPECT_EQ(evalVector("parent.size"), (V{1, 2, 3}));
}

TEST(GrammarExpression, NumbersInAllForms) {
    EXPECT_FLOAT_EQ(evalScalar("42"), 42.0f);
    EXPECT_FLOAT_EQ(evalScalar(".5"), 0.5f);
    EXPECT_FLOAT_EQ(evalScalar("5."), 5.0f);
    EXPECT_FLOAT_EQ(evalScalar("1e2"), 100.0f);
    EXPECT_FLOAT_EQ(evalScalar("2.5E-1"), 0.25f);
    EXPECT_FLOAT_EQ(evalScalar("3e+1"), 30.0f);
}

TEST(GrammarExpression, MultiplicationBindsTighterThanAddition) {
    EXPECT_FLOAT_EQ(evalScalar("1 + 2 * 3"), 7.0f);
    EXPECT_FLOAT_EQ(evalScalar("(1 + 2) * 3"), 9.0f);
    EXPECT_FLOAT_EQ(evalScalar("2 * 3 + 4 * 5"), 26.0f);
    EXPECT_FLOAT_EQ(evalScalar("1 + 6 / 2"), 4.0f);
}

TEST(GrammarExpression, OperatorsAreLeftAssociative) {
    EXPECT_FLOAT_EQ(evalScalar("10 - 4 - 3"), 3.0f);
    EXPECT_FLOAT_EQ(evalScalar("8 / 2 / 2"), 2.0f);
    EXPECT_FLOAT_EQ(evalScalar("8 / 2 * 2"), 8.0f);
}

TEST(GrammarExpression, UnaryMinus) {
    EXPECT_FLOAT_EQ(evalScalar("-p"), -1.5f);
    EXPECT_FLOAT_EQ(evalScalar("- -p"), 1.5f);
    EXPECT_FLOAT_EQ(evalScalar("2 - -3"), 5.0f);
    EXPECT_FLOAT_EQ(evalScalar("-2 * 3"), -6.0f);
    EXPECT_FLOAT_EQ(evalScalar("-v.y"), -5.0f) << "the swizzle applies before the minus";
    EXPECT_FLOAT_EQ(evalScalar("-(1 + 2) * 2"), -6.0f);
    EXPECT_EQ(evalVector("-v"), (V{-4, -5, -6}));
}

TEST(GrammarExpression, ScalarsBroadcastOverVectors) {
    EXPECT_EQ(evalVector("p"), (V{1.5f, 1.5f, 1.5f}));
    EXPECT_EQ(evalVector("(1, 2, 3) * 2"), (V{2, 4, 6}));
    EXPECT_EQ(evalVector("2 * (1, 2, 3)"), (V{2, 4, 6}));
    EXPECT_EQ(evalVector("scope.size * 0.5"), (V{1, 2, 3}));
    EXPECT_EQ(evalVector("v + 1"), (V{5, 6, 7}));
    EXPECT_EQ(evalVector("12 / scope.size"), (V{6, 3, 2}));
}

TEST(GrammarExpression, VectorsCombineComponentWise) {
    EXPECT_EQ(evalVector("v * scope.size"), (V{8, 20, 36}));
    EXPECT_EQ(evalVector("v - parent.size"), (V{3, 3, 3}));
    EXPECT_EQ(evalVector("(1, 2, 3) + (10, 20, 30)"), (V{11, 22, 33}));
}

TEST(GrammarExpression, VectorComponentsAreExpressions) {
    EXPECT_EQ(evalVector("(p, v.z, k * scope.size.x)"), (V{1.5f, 6.0f, 4.0f}));
    EXPECT_EQ(evalVector("(-1, -(2), 1 + 2)"), (V{-1, -2, 3}));
}

TEST(GrammarExpression, SwizzlesPickComponents) {
    EXPECT_FLOAT_EQ(evalScalar("v.x"), 4.0f);
    EXPECT_FLOAT_EQ(evalScalar("v.y"), 5.0f);
    EXPECT_FLOAT_EQ(evalScalar("v.z"), 6.0f);
    EXPECT_FLOAT_EQ(evalScalar("scope.size.y"), 4.0f);
    EXPECT_FLOAT_EQ(evalScalar("(1, 2, 3).z"), 3.0f);
    EXPECT_FLOAT_EQ(evalScalar("(v * 2).y"), 10.0f);
    EXPECT_FLOAT_EQ(evalScalar("min(v, 5).z"), 5.0f);
    EXPECT_EQ(evalVector("(v.z, v.y, v.x)"), (V{6, 5, 4}));
}

TEST(GrammarExpression, SwizzledScalarBroadcastsAgain) {
    EXPECT_EQ(evalVector("v.y"), (V{5, 5, 5}));
}

TEST(GrammarExpression, Functions) {
    EXPECT_FLOAT_EQ(evalScalar("min(3, p)"), 1.5f);
    EXPECT_FLOAT_EQ(evalScalar("max(3, p)"), 3.0f);
    EXPECT_FLOAT_EQ(evalScalar("abs(-2.5)"), 2.5f);
    EXPECT_FLOAT_EQ(evalScalar("sin(pi / 2)"), 1.0f);
    EXPECT_FLOAT_EQ(evalScalar("cos(0)"), 1.0f);
    EXPECT_FLOAT_EQ(evalScalar("sqrt(16)"), 4.0f);
    EXPECT_FLOAT_EQ(evalScalar("floor(2.7)"), 2.0f);
    EXPECT_FLOAT_EQ(evalScalar("floor(-2.5)"), -3.0f);
    EXPECT_FLOAT_EQ(evalScalar("max(min(p, 1), sqrt(abs(-0.25)))"), 1.0f);
}

TEST(GrammarExpression, FunctionsApplyPerComponentToVectors) {
    EXPECT_EQ(evalVector("min(v, 5)"), (V{4, 5, 5}));
    EXPECT_EQ(evalVector("max(scope.size, (3, 3, 3))"), (V{3, 4, 6}));
    EXPECT_EQ(evalVector("abs(-v)"), (V{4, 5, 6}));
    EXPECT_EQ(evalVector("floor(v / 4)"), (V{1, 1, 1}));
}

TEST(GrammarExpression, AttrsAndPiAreConstants) {
    EXPECT_FLOAT_EQ(evalScalar("k * 3"), 6.0f);
    EXPECT_FLOAT_EQ(evalScalar("pi"), float(M_PI));
    EXPECT_EQ(evalVector("(k, -k, k * k)"), (V{2, -2, 4}));
}

TEST(GrammarExpression, ParamsReadTheGenesParameterBlock) {
    Inputs in;
    in.params = {7.0f, -1.0f, -2.0f, -3.0f};
    EXPECT_FLOAT_EQ(evalScalar("p", in), 7.0f);
    EXPECT_EQ(evalVector("v", in), (V{-1, -2, -3}));
    EXPECT_EQ(evalVector("v * p", in), (V{-7, -14, -21}));
}

TEST(GrammarExpression, ExpressionsSeeTheScopeAtEvaluationTime) {
    Inputs in;
    in.scope = {10, 20, 30};
    EXPECT_FLOAT_EQ(evalScalar("scope.size.z - parent.size.z", in), 27.0f);
}

TEST(GrammarExpression, DivisionByZeroFollowsIeee) {
    EXPECT_TRUE(std::isinf(evalScalar("1 / 0")));
    EXPECT_TRUE(std::isnan(evalScalar("sqrt(-1)")));
}


TEST(GrammarExpression, MaxStackRecordsTheDeepestExpression) {
    const Grammar g = parseGrammar(ruleAround("rotate x " + test::rightNested(4)), "expr.grammar");
    EXPECT_EQ(g.maxStack, 5);
    EXPECT_FLOAT_EQ(evalScalar(test::rightNested(4)), 5.0f);
}

TEST(GrammarExpression, StackOfExactlyTheLimitIsAccepted) {
    const std::string e = test::rightNested(kMaxExpressionStack - 1);
    const Grammar g = parseGrammar(ruleAround("rotate x " + e), "expr.grammar");
    EXPECT_EQ(g.maxStack, kMaxExpressionStack);
    EXPECT_FLOAT_EQ(evalScalar(e), float(kMaxExpressionStack));
    EXPECT_THROW(parseGrammar(ruleAround("rotate x " + test::rightNested(kMaxExpressionStack)), "expr.grammar"), InputError);
}

TEST(GrammarExpression, LongLeftLeaningChainsNeedLittleStack) {
    std::string e = "0";
    for (int i = 0; i < 1000; ++i) e += " + 1";
    const Grammar g = parseGrammar(ruleAround("rotate x " + e), "expr.grammar");
    EXPECT_EQ(g.maxStack, 2);
    EXPECT_FLOAT_EQ(evalScalar(e), 1000.0f);
}

TEST(GrammarExpression, ExpressionsEndWhereTheNextStatementBegins) {
    const Grammar g = parseGrammar(ruleAround("scale v\n  rotate y p * 2\n  translate (0, 1, 0) box"), "expr.grammar");
    const Rule& r = g.rules[0];
    ASSERT_EQ(r.statements.size(), 4u);
    EXPECT_EQ(r.statements[0].kind, StatementKind::Scale);
    EXPECT_EQ(r.statements[1].kind, StatementKind::Rotate);
    EXPECT_EQ(r.statements[2].kind, StatementKind::Translate);
    EXPECT_EQ(r.statements[3].kind, StatementKind::Primitive);
    EXPECT_EQ(r.statements[3].primitive, PrimitiveKind::Box);
}

}  // namespace
}  // namespace shapevo
