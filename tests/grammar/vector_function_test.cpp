// length, dot and distance of 3-vectors are the plain float arithmetic they stand for, in the
// documented order (sqrt((x*x + y*y) + z*z) and so on), on numbers, parameters and the scope's
// frame slots; `length` stays usable as a parameter name (tree.grammar has one).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace vector_function_test {

/// The value of scalar `expr` (the angle of a rotate) with the parameter block `block`: p is
/// float 0, v floats 1..3, and the scope's frame slots hold what `block` holds there.
float evaluated(const std::string& expr, const std::vector<float>& block) {
    const Grammar g = parseGrammar("start A\nrule A {\n  param p = uniform(0, 10)\n  param v = uniform((0, 0, 0), (10, 10, 10))\n"
                                   "  rotate x " + expr + "\n}\n", "vector.grammar");
    const Rule& r = g.rules[0];
    const Statement& s = r.statements.back();
    EXPECT_EQ(s.kind, StatementKind::Rotate);
    const float size[3] = {2, 3, 4};
    float stack[kMaxExpressionStack];
    return evaluate(g, s.expr[0], block.data(), size, size, stack);
}

std::vector<float> block() {
    std::vector<float> b(kParamBlockFloats, 0.0f);
    b[0] = 0.7f;
    b[1] = 1.1f, b[2] = -2.3f, b[3] = 0.37f;  // v
    const float frame[12] = {3.25f, -1.5f, 0.125f, 0.6f, 0.8f, 0.0f, -0.8f, 0.6f, 0.0f, 0.0f, 0.0f, 1.0f};
    for (int k = 0; k < 12; ++k) b[kScopeOriginSlot + k] = frame[k];
    return b;
}

TEST(VectorFunctions, LengthDotAndDistanceArePlainFloatArithmetic) {
    const std::vector<float> b = block();
    const float vx = b[1], vy = b[2], vz = b[3], ox = b[kScopeOriginSlot], oy = b[kScopeOriginSlot + 1],
                oz = b[kScopeOriginSlot + 2];
    EXPECT_EQ(evaluated("length(v)", b), std::sqrt((vx * vx + vy * vy) + vz * vz));
    EXPECT_EQ(evaluated("length((3, 4, 12))", b), 13.0f);
    EXPECT_EQ(evaluated("dot(v, scope.origin)", b), (vx * ox + vy * oy) + vz * oz);
    EXPECT_EQ(evaluated("dot(v, 2 * v)", b), (vx * (2 * vx) + vy * (2 * vy)) + vz * (2 * vz));
    const float dx = vx - ox, dy = vy - oy, dz = vz - oz;
    EXPECT_EQ(evaluated("distance(v, scope.origin)", b), std::sqrt((dx * dx + dy * dy) + dz * dz));
    EXPECT_EQ(evaluated("distance(scope.origin, scope.origin)", b), 0.0f);
    EXPECT_EQ(evaluated("dot(scope.axis.x, scope.axis.y)", b), 0.0f);
    EXPECT_EQ(evaluated("length(scope.axis.z) + p", b), 1.0f + b[0]);
    EXPECT_EQ(evaluated("scope.axis.y.x + scope.origin.z", b), -0.8f + 0.125f);
    EXPECT_EQ(evaluated("length(scope.size - (2, 3, 4))", b), 0.0f);
}

TEST(VectorFunctions, NestedCallsCompileEachArgumentOnce) {
    // length of a vector of lengths, 20 deep: the code grows linearly, not 3^20.
    std::string e = "v";
    for (int k = 0; k < 20; ++k) e = "(length(" + e + "), 1, 1)";
    const Grammar g = parseGrammar("start A\nrule A {\n  param v = uniform((0, 0, 0), (1, 1, 1))\n  rotate x length(" + e + ")\n}\n",
                                   "nested.grammar");
    EXPECT_LT(g.code.size(), 400u);
}

TEST(VectorFunctions, LengthDotAndDistanceRemainUsableAsNames) {
    const Grammar g = parseGrammar("start A\nrule A {\n  param length = uniform(1, 2)\n  let distance = length * 2\n"
                                   "  size (length, distance, length((1, 0, 0)))\n  box\n}\n", "names.grammar");
    EXPECT_EQ(g.rules[0].params.at(0).name, "length");
    EXPECT_TRUE(isReservedName("min"));
    EXPECT_FALSE(isReservedName("length"));
    EXPECT_FALSE(isReservedName("piece"));
}

}  // namespace vector_function_test
}  // namespace shapevo
