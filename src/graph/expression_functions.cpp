// The whitelisted functions (expression_functions.hpp): Python's int/float/str/abs/min/max/round,
// random.* drawn from the frame's DrawSource (Python's formulas), the trigonometry of np and math,
// and the original's vector helpers. Numeric parsing and rounding live in expression_numeric.cpp.
#include "graph/expression_functions.hpp"

#include <cmath>

#include "graph/expression_numeric.hpp"
#include "graph/expression_operators.hpp"
#include "graph/value_compare.hpp"

namespace shapevo::graph {
namespace functions_detail {

constexpr FunctionInfo kFunctions[] = {
    {"int", Function::Int, 1, 1},
    {"float", Function::Float, 1, 1},
    {"str", Function::Str, 1, 1},
    {"abs", Function::Abs, 1, 1},
    {"min", Function::Min, 1, -1},
    {"max", Function::Max, 1, -1},
    {"round", Function::Round, 1, 2},
    {"random.random", Function::RandomRandom, 0, 0},
    {"random.uniform", Function::RandomUniform, 2, 2},
    {"random.randint", Function::RandomRandint, 2, 2},
    {"random.choice", Function::RandomChoice, 1, 1},
    {"np.arctan2", Function::Atan2, 2, 2},
    {"math.atan2", Function::Atan2, 2, 2},
    {"np.sin", Function::NpSin, 1, 1},
    {"np.cos", Function::NpCos, 1, 1},
    {"np.sqrt", Function::NpSqrt, 1, 1},
    {"math.sin", Function::MathSin, 1, 1},
    {"math.cos", Function::MathCos, 1, 1},
    {"math.sqrt", Function::MathSqrt, 1, 1},
    {"norm", Function::Norm, 1, 1},
    {"normalize", Function::Normalize, 1, 1},
    {"perp_left", Function::PerpLeft, 1, 1},
    {"perp_right", Function::PerpRight, 1, 1},
    {"cross", Function::Cross, 2, 2},
    {"angle", Function::Angle, 1, 2},
    {"rotate", Function::Rotate, 2, 3},
};

double numberArgument(const Value& v, const char* function) {
    double d = 0;
    if (!numberOf(v, d))
        throw EvaluationError(std::string(function) + "() needs a number, got '" + typeName(v) + "'");
    return d;
}

std::int64_t intArgument(const Value& v, const char* function) {
    if (const std::int64_t* i = v.asInt()) return *i;
    if (const bool* b = v.asBool()) return *b ? 1 : 0;
    throw EvaluationError(std::string(function) + "() needs an int, got '" + typeName(v) + "'");
}

Vec2 vectorArgument(const Value& v, const char* function) {
    if (const Vec2* p = v.asVec()) return *p;
    throw EvaluationError(std::string(function) + "() needs a Vec, got '" + typeName(v) + "'");
}

// Vec(): an element's position (a vertex's) or a vector itself.
Vec2 pointOf(const Value& v) {
    if (const Vec2* p = v.asVec()) return *p;
    if (const ElementRef* e = v.asElement()) {
        if (!e->isVertex) throw EvaluationError("Vec() of an edge: only vertices have a position");
        return e->position;
    }
    throw EvaluationError(std::string("Vec() needs a vertex or a Vec, got '") + typeName(v) + "'");
}

double mathFunction(Function f, double x) {
    switch (f) {
        case Function::MathSin:
        case Function::MathCos:
            if (std::isinf(x)) throw EvaluationError("math domain error");
            return f == Function::MathSin ? std::sin(x) : std::cos(x);
        case Function::MathSqrt:
            if (x < 0) throw EvaluationError("math domain error");
            return std::sqrt(x);
        case Function::NpSin: return std::sin(x);
        case Function::NpCos: return std::cos(x);
        default: return std::sqrt(x);  // np.sqrt: nan below 0, as numpy
    }
}

void minOrMaxOfSequence(bool isMax, const Value& seq, Value& out) {
    const char* name = isMax ? "max" : "min";
    if (const Tuple* t = seq.asTuple()) {
        if ((*t)->empty()) throw EvaluationError(std::string(name) + "() arg is an empty sequence");
        const Value* best = &(**t)[0];
        for (const Value& item : **t)
            if (compareValues(isMax ? CompareOp::Gt : CompareOp::Lt, item, *best)) best = &item;
        out = *best;
        return;
    }
    if (const std::string* s = seq.asString()) {
        if (s->empty()) throw EvaluationError(std::string(name) + "() arg is an empty sequence");
        char best = (*s)[0];
        for (const char c : *s)
            if (isMax ? (unsigned char)c > (unsigned char)best : (unsigned char)c < (unsigned char)best) best = c;
        out = Value(std::string(1, best));
        return;
    }
    throw EvaluationError(std::string("'") + typeName(seq) + "' object is not iterable");
}

void randomFunction(Function f, const Value* const* args, const EvaluationFrame& frame, Value& out) {
    if (!frame.draws) throw EvaluationError("random draws are not available here");
    DrawSource& draws = *frame.draws;
    switch (f) {
        case Function::RandomRandom: out = Value(draws.uniform(DrawPurpose::Expression)); return;
        case Function::RandomUniform: {
            const double a = numberArgument(*args[0], "random.uniform");
            const double b = numberArgument(*args[1], "random.uniform");
            out = Value(a + (b - a) * draws.uniform(DrawPurpose::Expression));
            return;
        }
        case Function::RandomRandint: {
            const std::int64_t a = intArgument(*args[0], "random.randint");
            const std::int64_t b = intArgument(*args[1], "random.randint");
            if (b < a) throw EvaluationError("random.randint: empty range (b < a)");
            const std::uint64_t span = std::uint64_t(b) - std::uint64_t(a) + 1;  // 0: the whole 64-bit range
            const std::uint64_t r = span == 0 ? (draws.below(UINT64_MAX, DrawPurpose::Expression) << 1) ^
                                                    draws.below(2, DrawPurpose::Expression)
                                              : draws.below(span, DrawPurpose::Expression);
            out = Value(std::int64_t(std::uint64_t(a) + r));
            return;
        }
        default: {
            const Value& seq = *args[0];
            if (const Tuple* t = seq.asTuple()) {
                if ((*t)->empty()) throw EvaluationError("Cannot choose from an empty sequence");
                out = (**t)[draws.below((*t)->size(), DrawPurpose::Expression)];
                return;
            }
            if (const std::string* s = seq.asString()) {
                if (s->empty()) throw EvaluationError("Cannot choose from an empty sequence");
                out = Value(std::string(1, (*s)[draws.below(s->size(), DrawPurpose::Expression)]));
                return;
            }
            throw EvaluationError(std::string("random.choice() needs a tuple, got '") + typeName(seq) + "'");
        }
    }
}

void vectorFunction(Function f, const Value* const* args, int count, Value& out) {
    switch (f) {
        case Function::VecOf: out = Value(pointOf(*args[0])); return;
        case Function::VecFromTo: {
            const Vec2 a = pointOf(*args[0]), b = pointOf(*args[1]);
            out = Value(Vec2{b.x - a.x, b.y - a.y});
            return;
        }
        case Function::VecXY:
            out = Value(Vec2{numberArgument(*args[0], "Vec"), numberArgument(*args[1], "Vec")});
            return;
        case Function::Norm: {
            const Vec2 v = vectorArgument(*args[0], "norm");
            out = Value(std::hypot(v.x, v.y));
            return;
        }
        case Function::Normalize: {
            const Vec2 v = vectorArgument(*args[0], "normalize");
            const double n = std::hypot(v.x, v.y);
            if (n == 0) throw EvaluationError("normalize() of a zero vector");
            out = Value(Vec2{v.x / n, v.y / n});
            return;
        }
        case Function::PerpLeft: {
            const Vec2 v = vectorArgument(*args[0], "perp_left");
            out = Value(Vec2{-v.y, v.x});
            return;
        }
        case Function::PerpRight: {
            const Vec2 v = vectorArgument(*args[0], "perp_right");
            out = Value(Vec2{v.y, -v.x});
            return;
        }
        case Function::Cross: {
            const Vec2 a = vectorArgument(*args[0], "cross"), b = vectorArgument(*args[1], "cross");
            out = Value(a.x * b.y - a.y * b.x);
            return;
        }
        case Function::Angle: {
            const Vec2 a = vectorArgument(*args[0], "angle");
            if (count == 1) {
                out = Value(std::atan2(a.y, a.x));
                return;
            }
            const Vec2 b = vectorArgument(*args[1], "angle");
            out = Value(std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y));
            return;
        }
        default: {  // rotate(v, radians[, center])
            const Vec2 v = vectorArgument(*args[0], "rotate");
            const double r = numberArgument(*args[1], "rotate");
            const Vec2 c = count == 3 ? vectorArgument(*args[2], "rotate") : Vec2{};
            const double cs = std::cos(r), sn = std::sin(r);
            const double dx = v.x - c.x, dy = v.y - c.y;
            out = Value(Vec2{c.x + cs * dx - sn * dy, c.y + sn * dx + cs * dy});
            return;
        }
    }
}

}  // namespace functions_detail

const FunctionInfo* findFunction(std::string_view name) {
    for (const FunctionInfo& f : functions_detail::kFunctions)
        if (f.name == name) return &f;
    return nullptr;
}

void callFunction(Function f, const Value* const* args, int count, const EvaluationFrame& frame, Value& out) {
    using namespace functions_detail;
    switch (f) {
        case Function::Int: out = Value(pythonInt(*args[0])); return;
        case Function::Float: out = Value(pythonFloat(*args[0])); return;
        case Function::Str: {
            std::string s;
            appendValueText(s, *args[0]);
            checkStringSize(s.size());
            out = Value(std::move(s));
            return;
        }
        case Function::Abs: {
            if (const double* d = args[0]->asFloat()) {
                out = Value(std::fabs(*d));
                return;
            }
            const std::int64_t i = intArgument(*args[0], "abs");
            if (i == INT64_MIN) throw EvaluationError("integer overflow (beyond 64 bits)");
            out = Value(i < 0 ? -i : i);
            return;
        }
        case Function::Min:
        case Function::Max: minOrMaxOfSequence(f == Function::Max, *args[0], out); return;
        case Function::Round: pythonRound(*args[0], count == 2 ? args[1] : nullptr, out); return;
        case Function::RandomRandom:
        case Function::RandomUniform:
        case Function::RandomRandint:
        case Function::RandomChoice: randomFunction(f, args, frame, out); return;
        case Function::Atan2:
            out = Value(std::atan2(numberArgument(*args[0], "arctan2"), numberArgument(*args[1], "arctan2")));
            return;
        case Function::NpSin:
        case Function::NpCos:
        case Function::NpSqrt:
        case Function::MathSin:
        case Function::MathCos:
        case Function::MathSqrt: out = Value(mathFunction(f, numberArgument(*args[0], "math"))); return;
        default: vectorFunction(f, args, count, out); return;
    }
}

}  // namespace shapevo::graph
