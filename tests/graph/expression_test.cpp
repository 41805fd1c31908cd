// The graph grammars' expression language (graph/expression.hpp): Python's exact results for
// every literal, operator and function (a table computed by CPython, make_expression_table.py),
// element and vector access, short-circuits that skip random draws, compile errors that name the
// offending token at its offset, evaluation errors, and the bounds (depth, size, built strings).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "graph/expression.hpp"

namespace shapevo::graph {
namespace expr_test {

// Counts the draws it answers (uniform: 0.25 each time; below(n): n - 1).
class CountingDraws final : public DrawSource {
public:
    int count = 0;
    double uniform(DrawPurpose) override { return ++count, 0.25; }
    std::uint64_t below(std::uint64_t n, DrawPurpose) override { return ++count, n - 1; }
};

// A fixed scene: slots self_, attr, attrs, v1, arg0, old, s, t, n.
struct Scene {
    AttrNames names;
    NameSlots slots;
    AttrMap vertexAttrs, edgeAttrs;
    std::vector<Value> values;
    CountingDraws draws;

    Scene() {
        for (const char* n : {"self_", "attr", "attrs", "v1", "arg0", "old", "s", "t", "n"}) slots.add(n);
        vertexAttrs.set(names.intern("size"), Value("2.5"));
        vertexAttrs.set(names.intern(".generation"), Value(3));
        vertexAttrs.set(names.intern("label"), Value("Branch"));
        edgeAttrs.set(names.intern("length"), Value(4.0));
        const ElementRef vertex{&vertexAttrs, true, Vec2{1.0, 2.0}};
        const ElementRef edge{&edgeAttrs, false, Vec2{}};
        values = {Value(vertex), Value("7"), Value(vertex), Value(Vec2{3.0, 4.0}), Value(edge), Value(),
                  Value(Vec2{1.0, 1.0}), Value(Tuple(std::make_shared<const std::vector<Value>>(
                                              std::vector<Value>{Value(1), Value(2.5), Value("x")}))),
                  Value(5)};
    }
    CompiledExpression compile(const std::string& text) { return compileExpression(text, slots, names); }
    Value run(const std::string& text) {
        const CompiledExpression e = compile(text);
        return e.evaluate(EvaluationFrame{values.data(), values.size(), &names, &draws});
    }
    std::string show(const std::string& text) { return toText(run(text)); }
};

// The message and offset of compiling `text`, or "compiled" if it compiled.
struct CompileFailure {
    std::string message;
    std::size_t offset = 0;
};
CompileFailure compileFailure(const std::string& text) {
    Scene scene;
    try {
        scene.compile(text);
    } catch (const ExpressionError& e) {
        return {e.what(), e.offset()};
    }
    return {"compiled", 0};
}

struct PythonCase {
    const char* expression;
    const char* expected;
};
constexpr PythonCase kPythonCases[] = {
#include "expression_python_table.inc"
};

}  // namespace expr_test

using namespace expr_test;

TEST(Expression, EveryTableExpressionGivesPythonsStr) {
    int checked = 0;
    for (const PythonCase& c : kPythonCases) {
        Scene scene;
        std::string got;
        try {
            got = scene.show(c.expression);
        } catch (const EvaluationError&) {
            got = "!error";
        }
        EXPECT_EQ(got, c.expected) << "expression: " << c.expression;
        ++checked;
    }
    EXPECT_GT(checked, 400);
}

TEST(Expression, FloatsPrintAsPythonsRepr) {
    Scene s;
    EXPECT_EQ(s.show("0.1 + 0.2"), "0.30000000000000004");
    EXPECT_EQ(s.show("1e16"), "1e+16");
    EXPECT_EQ(s.show("1.0"), "1.0");
    EXPECT_EQ(s.show("-0.0"), "-0.0");
    EXPECT_EQ(s.show("float('inf')"), "inf");
    EXPECT_EQ(s.show("-float('inf')"), "-inf");
    EXPECT_EQ(s.show("float('nan')"), "nan");
    EXPECT_EQ(s.show("1e-05"), "1e-05");
    EXPECT_EQ(s.show("0.0001"), "0.0001");
    EXPECT_EQ(s.show("1.5e300"), "1.5e+300");
}

TEST(Expression, ElementAttributesAndVectors) {
    Scene s;
    EXPECT_EQ(s.show("float(arg0.attr['length']) / 2"), "2.0");
    EXPECT_EQ(s.show("self_.attr['.generation'] + 1"), "4");
    EXPECT_EQ(s.show("attrs['label'] == 'Branch'"), "True");
    EXPECT_EQ(s.show("int(attr) * 2"), "14");
    EXPECT_EQ(s.show("v1.x + v1.y"), "7.0");
    EXPECT_EQ(s.show("Vec(self_)"), "Vec(1.0, 2.0)");
    EXPECT_EQ(s.show("Vec(self_, v1)"), "Vec(2.0, 2.0)");
    EXPECT_EQ(s.show("Vec(x1=1, y1=-2)"), "Vec(1.0, -2.0)");
    EXPECT_EQ(s.show("Vec(vec1=s, vec2=v1)"), "Vec(2.0, 3.0)");
    EXPECT_EQ(s.show("Vec(vec2=v1, vec1=s)"), "Vec(2.0, 3.0)");
    EXPECT_EQ(s.show("norm(v1)"), "5.0");
    EXPECT_EQ(s.show("normalize(v1)"), "Vec(0.6, 0.8)");
    EXPECT_EQ(s.show("perp_left(v1)"), "Vec(-4.0, 3.0)");
    EXPECT_EQ(s.show("perp_right(v1)"), "Vec(4.0, -3.0)");
    EXPECT_EQ(s.show("cross(v1, s)"), "-1.0");
    EXPECT_EQ(s.show("v1 * s"), "7.0");  // the dot product
    EXPECT_EQ(s.show("v1 + s"), "Vec(4.0, 5.0)");
    EXPECT_EQ(s.show("v1 - s"), "Vec(2.0, 3.0)");
    EXPECT_EQ(s.show("2 * v1"), "Vec(6.0, 8.0)");
    EXPECT_EQ(s.show("v1 * 0.5"), "Vec(1.5, 2.0)");
    EXPECT_EQ(s.show("v1 / 2"), "Vec(1.5, 2.0)");
    EXPECT_EQ(s.show("-v1"), "Vec(-3.0, -4.0)");
    EXPECT_EQ(s.show("v1 == Vec(x1=3, y1=4)"), "True");
    EXPECT_EQ(s.show("t[-1] + t[0] * 'y'"), "xy");
    EXPECT_EQ(s.show("str(t)"), "(1, 2.5, 'x')");
    EXPECT_EQ(s.show("old == None"), "True");
    // angle(v) = atan2(v.y, v.x); angle(a, b) = the signed angle from a to b.
    EXPECT_DOUBLE_EQ(*s.run("angle(s)").asFloat(), M_PI / 4);
    EXPECT_DOUBLE_EQ(*s.run("angle(Vec(x1=1, y1=0), Vec(x1=0, y1=1))").asFloat(), M_PI / 2);
    EXPECT_DOUBLE_EQ(*s.run("angle(Vec(x1=0, y1=1), Vec(x1=1, y1=0))").asFloat(), -M_PI / 2);
    const Value r = s.run("rotate(Vec(x1=2, y1=1), pi / 2, Vec(x1=1, y1=1))");
    EXPECT_NEAR(r.asVec()->x, 1.0, 1e-15);
    EXPECT_NEAR(r.asVec()->y, 2.0, 1e-15);
    const Value r0 = s.run("rotate(Vec(x1=1, y1=0), pi)");
    EXPECT_NEAR(r0.asVec()->x, -1.0, 1e-15);
    EXPECT_EQ(s.show("f'M {v1.x*35} {v1.y*35}'"), "M 105.0 140.0");
}

TEST(Expression, RandomCallsDrawFromTheSourceWithPythonsFormulas) {
    Scene s;
    EXPECT_EQ(s.show("random.random()"), "0.25");
    EXPECT_EQ(s.show("random.uniform(2, 6)"), "3.0");
    EXPECT_EQ(s.show("random.randint(3, 5)"), "5");  // below(3) answers 2
    EXPECT_EQ(s.show("random.choice(('a', 'b', 'c'))"), "c");
    EXPECT_EQ(s.draws.count, 4);
    EXPECT_THROW(s.run("random.randint(5, 3)"), EvaluationError);
    EXPECT_THROW(s.run("random.choice(())"), EvaluationError);
    SeededDraws seeded(7);
    const CompiledExpression e = s.compile("random.uniform(-1, 1)");
    const Value a = e.evaluate(EvaluationFrame{s.values.data(), s.values.size(), &s.names, &seeded});
    EXPECT_GE(*a.asFloat(), -1.0);
    EXPECT_LT(*a.asFloat(), 1.0);
}

TEST(Expression, AndOrAndConditionalsSkipTheSideTheyDoNotNeed) {
    Scene s;
    EXPECT_EQ(s.show("False and random.random()"), "False");
    EXPECT_EQ(s.show("1 or random.random()"), "1");
    EXPECT_EQ(s.show("2 if True else random.random()"), "2");
    EXPECT_EQ(s.show("1 > 2 > random.random()"), "False");
    EXPECT_EQ(s.draws.count, 0);
    EXPECT_EQ(s.show("True and random.random()"), "0.25");
    EXPECT_EQ(s.draws.count, 1);
    EXPECT_EQ(s.show("0 or 1/0 if False else 'ok'"), "ok");
}

TEST(Expression, CompiledFormKnowsItsSlotsConstancyAndDraws) {
    Scene s;
    const CompiledExpression c = s.compile("1 + 2 * 3");
    EXPECT_TRUE(c.isConstant());
    EXPECT_FALSE(c.drawsRandomly());
    EXPECT_TRUE(c.slotsRead().empty());
    const CompiledExpression e = s.compile("t[0] + n + v1.x + n + self_.attr['size'] * 0 if random.random() else 0");
    EXPECT_FALSE(e.isConstant());
    EXPECT_TRUE(e.drawsRandomly());
    EXPECT_EQ(e.slotsRead(), (std::vector<int>{0, 3, 7, 8}));
    EXPECT_FALSE(s.compile("random.choice((1, 2))").isConstant());
    const AttrKey before = s.names.find("brand_new");
    EXPECT_EQ(before, AttrNames::kNone);
    s.compile("self_.attr['brand_new']");
    EXPECT_NE(s.names.find("brand_new"), AttrNames::kNone);
}

TEST(Expression, EvaluationErrorsAreTyped) {
    Scene s;
    EXPECT_THROW(s.run("1 / 0"), EvaluationError);
    EXPECT_THROW(s.run("1 // 0"), EvaluationError);
    EXPECT_THROW(s.run("1.0 % 0"), EvaluationError);
    EXPECT_THROW(s.run("int('x')"), EvaluationError);
    EXPECT_THROW(s.run("int('3.5')"), EvaluationError);
    EXPECT_THROW(s.run("float('abc')"), EvaluationError);
    EXPECT_THROW(s.run("'a' < 1"), EvaluationError);
    EXPECT_THROW(s.run("'a' + 1"), EvaluationError);
    EXPECT_THROW(s.run("self_.x"), EvaluationError);  // .x is for vectors, not elements
    EXPECT_THROW(s.run("Vec(arg0)"), EvaluationError);  // an edge has no position
    EXPECT_THROW(s.run("t[3]"), EvaluationError);
    EXPECT_THROW(s.run("normalize(Vec(x1=0, y1=0))"), EvaluationError);
    EXPECT_THROW(s.run("math.sqrt(-1)"), EvaluationError);
    EXPECT_TRUE(std::isnan(*s.run("np.sqrt(-1)").asFloat()));
    EXPECT_THROW(s.run("9223372036854775807 + 1"), EvaluationError);
    EXPECT_THROW(s.run("-9223372036854775807 - 2"), EvaluationError);
    EXPECT_THROW(s.run("3037000500 * 3037000500"), EvaluationError);
    EXPECT_THROW(s.run("(-9223372036854775807 - 1) // -1"), EvaluationError);
    EXPECT_EQ(s.show("(-9223372036854775807 - 1) % -1"), "0");
    EXPECT_THROW(s.run("self_.attr['missing']"), MissingKeyError);
    EXPECT_THROW(s.run("attrs['nope'] == 1"), MissingKeyError);
    try {
        s.run("self_.attr['missing']");
    } catch (const MissingKeyError& e) {
        EXPECT_NE(std::string(e.what()).find("'missing'"), std::string::npos) << e.what();
    }
}

TEST(Expression, BuiltStringsAndTuplesAreBounded) {
    Scene s;
    EXPECT_EQ(s.run("'ab' * 1000").asString()->size(), 2000u);
    EXPECT_THROW(s.run("'ab' * 1000000"), EvaluationError);
    EXPECT_THROW(s.run("'a' * 600000 + 'b' * 600000"), EvaluationError);
    EXPECT_THROW(s.run("f\"{'a' * 700000}{'b' * 700000}\""), EvaluationError);
    EXPECT_THROW(s.run("('abcdefgh' * 1000,) * 1000"), EvaluationError);
    EXPECT_THROW(s.run("'x' * 9223372036854775807"), EvaluationError);
}

TEST(Expression, CompileErrorsNameTheTokenAndItsOffset) {
    struct Case {
        std::string text, fragment;
        std::size_t offset;
    };
    const std::vector<Case> cases = {
        {"__import__('os')", "'__import__': names starting with '__'", 0},
        {"open('x')", "unknown function 'open'", 0},
        {"1 + os.system('x')", "unknown name 'os'", 4},
        {"exec('1')", "unknown function 'exec'", 0},
        {"lambda: 1", "'lambda' is not supported", 0},
        {"[x for x in y]", "list displays and comprehensions", 0},
        {"self_.__class__", "'.__class__'", 6},
        {"2 * foo", "unknown name 'foo'", 4},
        {"random.seed(1)", "unknown function 'random.seed'", 0},
        {"norm(v1, v1)", "norm() takes 1 argument (2 given)", 0},
        {"1 + 'abc", "unterminated string literal", 4},
        {"f'{'", "f-string: expecting '}'", 2},
        {"f'{s!r}'", "f-string conversions ('!r')", 4},
        {"f'{s:.2f}'", "f-string format specs", 4},
        {"v1.norm", "attribute '.norm' is not allowed", 3},
        {"2 ** 3", "operator '**' is not supported", 2},
        {"1 +", "unexpected end of expression", 3},
        {"s(1)", "unknown function 's'", 0},
        {"(v1)(1)", "only the whitelisted functions may be called", 4},
        {"1, 2", "a top-level tuple needs parentheses", 1},
        {"x = 1", "unknown name 'x'", 0},
        {"t[1:2]", "slices are not supported", 3},
        {"1 if 2", "expected 'else'", 6},
        {"{'a': 1}", "dict and set displays", 0},
        {"1 in t", "operator 'in' is not supported", 2},
        {"007", "leading zeros", 0},
        {"1j", "imaginary numbers", 1},
        {"b'x'", "string prefix 'b'", 0},
        {"1 $ 2", "unexpected character '$'", 2},
        {"Vec(a=1)", "Vec takes", 0},
        {"int(x=1)", "int() takes no keyword arguments", 0},
        {"abs(-1, y1=2)", "abs() takes no keyword arguments", 0},
        {"'\\x4'", "truncated \\x escape", 1},
        {"self_.attr", "'.attr' must be followed by ['key']", 10},
        {"99999999999999999999", "integer literal too large", 0},
        {"math", "'math' may only prefix a whitelisted call", 0},
    };
    std::vector<std::string> messages;
    for (const Case& c : cases) {
        const CompileFailure f = compileFailure(c.text);
        EXPECT_NE(f.message.find(c.fragment), std::string::npos) << c.text << " -> " << f.message;
        EXPECT_EQ(f.offset, c.offset) << c.text << " -> " << f.message;
        messages.push_back(f.message);
    }
    std::sort(messages.begin(), messages.end());
    EXPECT_EQ(std::unique(messages.begin(), messages.end()), messages.end()) << "two cases share a message";
}

TEST(Expression, NestingAndSizeAreBoundedWithoutRecursingDeep) {
    const CompileFailure parens = compileFailure(std::string(30000, '(') + "1" + std::string(30000, ')'));
    EXPECT_NE(parens.message.find("nested deeper than 64"), std::string::npos) << parens.message;
    EXPECT_EQ(parens.offset, 64u);
    const CompileFailure manyParens = compileFailure(std::string(100000, '(') + "1" + std::string(100000, ')'));
    EXPECT_NE(manyParens.message.find("longer than 65536 bytes"), std::string::npos) << manyParens.message;
    const CompileFailure minus = compileFailure(std::string(50000, '-') + "1");
    EXPECT_NE(minus.message.find("nested deeper"), std::string::npos) << minus.message;
    const CompileFailure nots = compileFailure([] {
        std::string s;
        for (int i = 0; i < 10000; ++i) s += "not ";
        return s + "1";
    }());
    EXPECT_NE(nots.message.find("nested deeper"), std::string::npos) << nots.message;
    std::string chain = "1";
    for (int i = 0; i < 20000; ++i) chain += "+1";
    const CompileFailure longChain = compileFailure(chain);
    EXPECT_NE(longChain.message.find("chained operations"), std::string::npos) << longChain.message;
    const CompileFailure huge = compileFailure("'" + std::string(100 * 1024, 'a') + "'");
    EXPECT_NE(huge.message.find("longer than 65536 bytes"), std::string::npos) << huge.message;
    Scene s;
    EXPECT_EQ(s.show(std::string(60, '(') + "7" + std::string(60, ')')), "7");
    std::string sum = "0";
    for (int i = 0; i < 300; ++i) sum += "+1";
    EXPECT_EQ(s.show(sum), "300");
}

TEST(Expression, AdjacentLiteralsConcatenateAsInPython) {
    Scene s;
    EXPECT_EQ(s.show("'a' 'b'"), "ab");
    EXPECT_EQ(s.show("'n=' f'{n}' \"!\""), "n=5!");
}

TEST(Value, TruthEqualityAndText) {
    EXPECT_FALSE(truthy(Value()));
    EXPECT_FALSE(truthy(Value(0.0)));
    EXPECT_TRUE(truthy(Value("False")));
    EXPECT_TRUE(truthy(Value(std::nan(""))));
    EXPECT_FALSE(truthy(Value(Tuple(std::make_shared<const std::vector<Value>>()))));
    EXPECT_TRUE(equal(Value(false), Value(0)));
    EXPECT_TRUE(equal(Value(1), Value(1.0)));
    EXPECT_FALSE(equal(Value("1"), Value(1)));
    EXPECT_FALSE(equal(Value(std::int64_t(9007199254740993)), Value(9007199254740992.0)));
    EXPECT_EQ(toText(Value(0.1)), "0.1");
    EXPECT_EQ(toText(Value(1e16)), "1e+16");
    EXPECT_EQ(toText(Value(123.0)), "123.0");
    EXPECT_EQ(toText(Value(Vec2{1, -0.5})), "Vec(1.0, -0.5)");
    EXPECT_STREQ(typeName(Value(Vec2{})), "Vec");
    double d = 0;
    EXPECT_TRUE(numberOf(Value(true), d));
    EXPECT_EQ(d, 1.0);
    EXPECT_FALSE(numberOf(Value("1"), d));
    AttrNames names;
    EXPECT_EQ(names.intern("a"), 0u);
    EXPECT_EQ(names.intern("b"), 1u);
    EXPECT_EQ(names.intern("a"), 0u);
    EXPECT_EQ(names.find("c"), AttrNames::kNone);
}

}  // namespace shapevo::graph
