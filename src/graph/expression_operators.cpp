// The expression language's operators (expression_operators.hpp), with Python's results: the
// float floor division and modulo follow CPython's float_divmod step by step.
#include "graph/expression_operators.hpp"

#include <cmath>
#include <string>

#include "graph/value_compare.hpp"

namespace shapevo::graph {
namespace operators_detail {

const char* symbolOf(BinaryOp op) {
    static constexpr const char* kSymbols[] = {"+", "-", "*", "/", "//", "%"};
    return kSymbols[int(op)];
}

[[noreturn]] void unsupported(BinaryOp op, const Value& a, const Value& b) {
    throw EvaluationError(std::string("unsupported operand type(s) for ") + symbolOf(op) + ": '" + typeName(a) +
                          "' and '" + typeName(b) + "'");
}

[[noreturn]] void overflow() { throw EvaluationError("integer overflow (beyond 64 bits)"); }

// An int-like operand (bool or int).
bool intOf(const Value& v, std::int64_t& out) {
    if (const std::int64_t* i = v.asInt()) return out = *i, true;
    if (const bool* b = v.asBool()) return out = *b ? 1 : 0, true;
    return false;
}

void intOperation(BinaryOp op, std::int64_t x, std::int64_t y, Value& out) {
    std::int64_t r = 0;
    switch (op) {
        case BinaryOp::Add:
            if (__builtin_add_overflow(x, y, &r)) overflow();
            break;
        case BinaryOp::Sub:
            if (__builtin_sub_overflow(x, y, &r)) overflow();
            break;
        case BinaryOp::Mul:
            if (__builtin_mul_overflow(x, y, &r)) overflow();
            break;
        case BinaryOp::Div:
            if (y == 0) throw EvaluationError("division by zero");
            out = Value(double(x) / double(y));
            return;
        case BinaryOp::FloorDiv:
            if (y == 0) throw EvaluationError("integer division or modulo by zero");
            if (x == INT64_MIN && y == -1) overflow();
            r = x / y;
            if (x % y != 0 && ((x < 0) != (y < 0))) --r;
            break;
        case BinaryOp::Mod:
            if (y == 0) throw EvaluationError("integer division or modulo by zero");
            if (y == -1) {
                r = 0;
                break;
            }
            r = x % y;
            if (r != 0 && ((r < 0) != (y < 0))) r += y;
            break;
    }
    out = Value(r);
}

void floatOperation(BinaryOp op, double x, double y, Value& out) {
    switch (op) {
        case BinaryOp::Add: out = Value(x + y); return;
        case BinaryOp::Sub: out = Value(x - y); return;
        case BinaryOp::Mul: out = Value(x * y); return;
        case BinaryOp::Div:
            if (y == 0) throw EvaluationError("float division by zero");
            out = Value(x / y);
            return;
        case BinaryOp::FloorDiv:
        case BinaryOp::Mod: {
            if (y == 0) throw EvaluationError(op == BinaryOp::Mod ? "float modulo by zero" : "float floor division by zero");
            double mod = std::fmod(x, y);
            double div = (x - mod) / y;
            if (mod != 0) {
                if ((y < 0) != (mod < 0)) {
                    mod += y;
                    div -= 1.0;
                }
            } else {
                mod = std::copysign(0.0, y);
            }
            if (op == BinaryOp::Mod) {
                out = Value(mod);
                return;
            }
            double floorDiv;
            if (div != 0) {
                floorDiv = std::floor(div);
                if (div - floorDiv > 0.5) floorDiv += 1.0;
            } else {
                floorDiv = std::copysign(0.0, x / y);
            }
            out = Value(floorDiv);
            return;
        }
    }
}

void repeatString(const std::string& s, std::int64_t n, Value& out) {
    if (n <= 0 || s.empty()) {
        out = Value(std::string());
        return;
    }
    if (std::uint64_t(n) > kMaxBuiltBytes / s.size()) checkStringSize(kMaxBuiltBytes + 1);
    std::string r;
    r.reserve(s.size() * std::size_t(n));
    for (std::int64_t i = 0; i < n; ++i) r += s;
    out = Value(std::move(r));
}

void repeatTuple(const Tuple& t, std::int64_t n, Value& out) {
    auto items = std::make_shared<std::vector<Value>>();
    if (n > 0 && !t->empty()) {
        if (std::uint64_t(n) > kMaxBuiltBytes / (16 * t->size()))
            throw EvaluationError("tuple result too large (over " + std::to_string(kMaxBuiltBytes) + " bytes)");
        checkTupleSize(*t);
        items->reserve(t->size() * std::size_t(n));
        for (std::int64_t i = 0; i < n; ++i) items->insert(items->end(), t->begin(), t->end());
        checkTupleSize(*items);
    }
    out = Value(Tuple(std::move(items)));
}

bool sequenceOperation(BinaryOp op, const Value& a, const Value& b, Value& out) {
    std::int64_t n = 0;
    if (op == BinaryOp::Add) {
        if (a.asString() && b.asString()) {
            checkStringSize(a.asString()->size() + b.asString()->size());
            out = Value(*a.asString() + *b.asString());
            return true;
        }
        if (a.asTuple() && b.asTuple()) {
            auto items = std::make_shared<std::vector<Value>>(**a.asTuple());
            items->insert(items->end(), (*b.asTuple())->begin(), (*b.asTuple())->end());
            checkTupleSize(*items);
            out = Value(Tuple(std::move(items)));
            return true;
        }
        return false;
    }
    if (op != BinaryOp::Mul) return false;
    const Value* seq = nullptr;
    if (intOf(b, n) && (a.asString() || a.asTuple()))
        seq = &a;
    else if (intOf(a, n) && (b.asString() || b.asTuple()))
        seq = &b;
    if (!seq) return false;
    if (seq->asString())
        repeatString(*seq->asString(), n, out);
    else
        repeatTuple(*seq->asTuple(), n, out);
    return true;
}

bool vectorOperation(BinaryOp op, const Value& a, const Value& b, Value& out) {
    const Vec2* u = a.asVec();
    const Vec2* v = b.asVec();
    double k = 0;
    if (u && v) {
        switch (op) {
            case BinaryOp::Add: out = Value(Vec2{u->x + v->x, u->y + v->y}); return true;
            case BinaryOp::Sub: out = Value(Vec2{u->x - v->x, u->y - v->y}); return true;
            case BinaryOp::Mul: out = Value(u->x * v->x + u->y * v->y); return true;  // the dot product
            default: return false;
        }
    }
    if (u && numberOf(b, k)) {
        if (op == BinaryOp::Mul) {
            out = Value(Vec2{u->x * k, u->y * k});
            return true;
        }
        if (op == BinaryOp::Div) {
            if (k == 0) throw EvaluationError("division of a vector by zero");
            out = Value(Vec2{u->x / k, u->y / k});
            return true;
        }
        return false;
    }
    if (v && op == BinaryOp::Mul && numberOf(a, k)) {
        out = Value(Vec2{k * v->x, k * v->y});
        return true;
    }
    return false;
}

}  // namespace operators_detail

void checkStringSize(std::size_t bytes) {
    if (bytes > kMaxBuiltBytes)
        throw EvaluationError("string result too long (over " + std::to_string(kMaxBuiltBytes) + " bytes)");
}

namespace operators_detail {

// Bytes a value holds, stopping early past the limit.
std::size_t contentBytes(const Value& v, std::size_t limit) {
    if (const std::string* s = v.asString()) return 16 + s->size();
    if (const Tuple* t = v.asTuple()) {
        std::size_t total = 16;
        for (const Value& item : **t) {
            total += contentBytes(item, limit);
            if (total > limit) break;
        }
        return total;
    }
    return 16;
}

}  // namespace operators_detail

void checkTupleSize(const std::vector<Value>& items) {
    std::size_t total = 0;
    for (const Value& item : items) {
        total += operators_detail::contentBytes(item, kMaxBuiltBytes);
        if (total > kMaxBuiltBytes)
            throw EvaluationError("tuple result too large (over " + std::to_string(kMaxBuiltBytes) + " bytes)");
    }
}

void binaryOperation(BinaryOp op, const Value& a, const Value& b, Value& out) {
    using namespace operators_detail;
    std::int64_t x = 0, y = 0;
    if (intOf(a, x) && intOf(b, y)) return intOperation(op, x, y, out);
    double fx = 0, fy = 0;
    if (numberOf(a, fx) && numberOf(b, fy)) return floatOperation(op, fx, fy, out);
    if (sequenceOperation(op, a, b, out)) return;
    if (vectorOperation(op, a, b, out)) return;
    unsupported(op, a, b);
}

void negateValue(const Value& a, Value& out) {
    std::int64_t x = 0;
    if (operators_detail::intOf(a, x)) {
        if (x == INT64_MIN) operators_detail::overflow();
        out = Value(-x);
    } else if (const double* d = a.asFloat()) {
        out = Value(-*d);
    } else if (const Vec2* v = a.asVec()) {
        out = Value(Vec2{-v->x, -v->y});
    } else {
        throw EvaluationError(std::string("bad operand type for unary -: '") + typeName(a) + "'");
    }
}

void plusValue(const Value& a, Value& out) {
    std::int64_t x = 0;
    if (operators_detail::intOf(a, x))
        out = Value(x);
    else if (a.asFloat() || a.asVec())
        out = a;
    else
        throw EvaluationError(std::string("bad operand type for unary +: '") + typeName(a) + "'");
}

namespace operators_detail {

bool fromOrder(CompareOp op, int c) {
    if (c == 2) return false;  // nan: every ordering is false
    switch (op) {
        case CompareOp::Lt: return c < 0;
        case CompareOp::Le: return c <= 0;
        case CompareOp::Gt: return c > 0;
        default: return c >= 0;
    }
}

}  // namespace operators_detail

bool compareValues(CompareOp op, const Value& a, const Value& b) {
    using namespace operators_detail;
    if (op == CompareOp::Eq) return equal(a, b);
    if (op == CompareOp::Ne) return !equal(a, b);
    if (isNumber(a) && isNumber(b)) return fromOrder(op, compareNumbers(a, b));
    if (a.asString() && b.asString()) {
        const int c = a.asString()->compare(*b.asString());
        return fromOrder(op, c < 0 ? -1 : (c > 0 ? 1 : 0));
    }
    if (a.asTuple() && b.asTuple()) {
        const auto& x = **a.asTuple();
        const auto& y = **b.asTuple();
        std::size_t i = 0;
        while (i < x.size() && i < y.size() && equal(x[i], y[i])) ++i;
        if (i < x.size() && i < y.size()) return compareValues(op, x[i], y[i]);
        return fromOrder(op, x.size() < y.size() ? -1 : (x.size() > y.size() ? 1 : 0));
    }
    static constexpr const char* kSymbols[] = {"==", "!=", "<", "<=", ">", ">="};
    throw EvaluationError(std::string("'") + kSymbols[int(op)] + "' not supported between instances of '" + typeName(a) +
                          "' and '" + typeName(b) + "'");
}

}  // namespace shapevo::graph
