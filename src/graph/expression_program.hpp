// The compiled form of one expression (internal to the expression files): a flat vector of
// nodes that refer to their children by index, a table of constants and a list of child
// indices for nodes with many operands (tuples, calls, f-strings, comparison chains). The
// evaluator walks it with one switch per node: no virtual call, no std::function, no allocation
// beyond the strings and tuples the expression itself builds.
#pragma once
#include <cstdint>
#include <vector>

#include "graph/expression.hpp"

namespace shapevo::graph {

/// Deepest tree the evaluator may recurse through (a long chain like 1+1+...+1 is a deep tree,
/// built by loops in the parser): a compile error beyond it, so evaluation cannot overflow the stack.
inline constexpr int kMaxExpressionTreeDepth = 400;
/// Largest str, and largest tuple (counted in bytes of its contents), an evaluation may build.
inline constexpr std::size_t kMaxBuiltBytes = 1u << 20;

enum class Op : std::uint8_t {
    Constant,   // a = constant index
    Slot,       // a = slot index
    Negate,     // a
    Plus,       // a (unary +)
    Not,        // a
    Binary,     // sub = BinaryOp, a, b
    And,        // a, b
    Or,         // a, b
    Compare,    // chain: a = first of `count` operands in `lists`, then count-1 CompareOps
    IfElse,     // a = condition, b = then, c = else
    Tuple,      // a = first of `count` items in `lists`
    Attribute,  // a = element, b = AttrKey  (X.attr['key'], attrs['key'])
    VecX,       // a
    VecY,       // a
    Index,      // a = sequence, b = index
    Call,       // sub = Function, a = first of `count` arguments in `lists`
    Format,     // f-string: a = first of `count` parts in `lists`, each appended as str()
};

enum class BinaryOp : std::uint8_t { Add, Sub, Mul, Div, FloorDiv, Mod };
enum class CompareOp : std::uint8_t { Eq, Ne, Lt, Le, Gt, Ge };

/// The whitelisted functions (expression_functions.cpp).
enum class Function : std::uint8_t {
    Int, Float, Str, Abs, Min, Max, Round,
    RandomRandom, RandomUniform, RandomRandint, RandomChoice,
    Atan2, NpSin, NpCos, NpSqrt, MathSin, MathCos, MathSqrt,
    VecOf,      // Vec(element) or Vec(vector)
    VecFromTo,  // Vec(a, b), Vec(vec1=a, vec2=b): b - a
    VecXY,      // Vec(x1=, y1=)
    Norm, Normalize, PerpLeft, PerpRight, Cross, Angle, Rotate,
};

struct Node {
    Op op = Op::Constant;
    std::uint8_t sub = 0;
    std::uint16_t count = 0;
    std::int32_t a = 0, b = 0, c = 0;
    std::uint32_t offset = 0;  // byte offset in the text, for messages
};

struct CompiledExpression::Program {
    std::vector<Node> nodes;
    std::vector<Value> constants;
    std::vector<std::int32_t> lists;
    std::int32_t root = 0;
    std::vector<int> slots;  // slots read, ascending, unique
    bool random = false;
};

/// Evaluates node `index`: returns a reference either to existing storage (a constant, a slot,
/// an attribute) or to `scratch`, which it fills.
const Value& evaluateNode(const CompiledExpression::Program& p, std::int32_t index, const EvaluationFrame& frame,
                          Value& scratch);

}  // namespace shapevo::graph
