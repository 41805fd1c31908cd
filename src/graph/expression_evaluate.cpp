// Evaluation of a compiled expression (expression_program.hpp): one recursive walk over the
// flat node vector, a switch per node. Reads (constants, slots, attributes) return references to
// where the value already lives; only results an operator, call or display builds go to the
// caller's scratch Value, so an evaluation allocates only for the strings and tuples it builds.
// The tree's depth is bounded at compile time (kMaxExpressionTreeDepth), so is the recursion.
#include <string>

#include "graph/expression_functions.hpp"
#include "graph/expression_operators.hpp"
#include "graph/value_compare.hpp"

namespace shapevo::graph {
namespace evaluate_detail {

using Program = CompiledExpression::Program;

const Value& attributeOf(const Value& target, const Node& n, const EvaluationFrame& frame) {
    const ElementRef* e = target.asElement();
    const auto keyName = [&] {
        const auto k = AttrKey(n.b);
        return frame.names && k < frame.names->size() ? frame.names->name(k) : std::string("#") + std::to_string(k);
    };
    if (!e || !e->attrs)
        throw EvaluationError("['" + keyName() + "'] needs an element, got '" + typeName(target) + "'");
    if (const Value* v = e->attrs->find(AttrKey(n.b))) return *v;
    throw MissingKeyError("missing attribute '" + keyName() + "'");
}

void indexInto(const Value& seq, const Value& index, Value& out) {
    std::int64_t i = 0;
    if (const std::int64_t* p = index.asInt())
        i = *p;
    else if (const bool* b = index.asBool())
        i = *b;
    else
        throw EvaluationError(std::string("indices must be integers, not '") + typeName(index) + "'");
    std::size_t size = 0;
    if (const Tuple* t = seq.asTuple())
        size = (*t)->size();
    else if (const std::string* s = seq.asString())
        size = s->size();
    else
        throw EvaluationError(std::string("'") + typeName(seq) + "' object is not subscriptable");
    if (i < 0) i += std::int64_t(size);
    if (i < 0 || i >= std::int64_t(size)) throw EvaluationError(std::string(typeName(seq)) + " index out of range");
    if (const Tuple* t = seq.asTuple())
        out = (**t)[std::size_t(i)];
    else
        out = Value(std::string(1, (*seq.asString())[std::size_t(i)]));
}

bool compareChain(const Program& p, const Node& n, const EvaluationFrame& frame) {
    const std::int32_t* operands = p.lists.data() + n.a;
    const std::int32_t* ops = operands + n.count;
    Value buffers[2];
    const Value* left = &evaluateNode(p, operands[0], frame, buffers[0]);
    for (int i = 1; i < n.count; ++i) {
        // The right operand goes to the buffer the left one does not occupy.
        Value& free = left == &buffers[0] ? buffers[1] : buffers[0];
        const Value& right = evaluateNode(p, operands[i], frame, free);
        if (!compareValues(CompareOp(ops[i - 1]), *left, right)) return false;
        left = &right;
    }
    return true;
}

const Value& minOrMaxOfArguments(const Program& p, const Node& n, const EvaluationFrame& frame, Value& scratch) {
    const bool isMax = Function(n.sub) == Function::Max;
    const std::int32_t* args = p.lists.data() + n.a;
    Value buffers[2];
    const Value* best = &evaluateNode(p, args[0], frame, buffers[0]);
    for (int i = 1; i < n.count; ++i) {
        Value& free = best == &buffers[0] ? buffers[1] : buffers[0];
        const Value& candidate = evaluateNode(p, args[i], frame, free);
        if (compareValues(isMax ? CompareOp::Gt : CompareOp::Lt, candidate, *best)) best = &candidate;
    }
    if (best != &buffers[0] && best != &buffers[1]) return *best;
    scratch = std::move(*const_cast<Value*>(best));
    return scratch;
}

const Value& call(const Program& p, const Node& n, const EvaluationFrame& frame, Value& scratch) {
    const Function f = Function(n.sub);
    if ((f == Function::Min || f == Function::Max) && n.count > 1) return minOrMaxOfArguments(p, n, frame, scratch);
    const std::int32_t* args = p.lists.data() + n.a;
    Value buffers[3];
    const Value* values[3] = {nullptr, nullptr, nullptr};
    for (int i = 0; i < n.count; ++i) values[i] = &evaluateNode(p, args[i], frame, buffers[i]);
    callFunction(f, values, n.count, frame, scratch);
    return scratch;
}

const Value& buildTuple(const Program& p, const Node& n, const EvaluationFrame& frame, Value& scratch) {
    auto items = std::make_shared<std::vector<Value>>();
    items->reserve(n.count);
    for (int i = 0; i < n.count; ++i) {
        Value item;
        const Value& v = evaluateNode(p, p.lists[std::size_t(n.a + i)], frame, item);
        if (&v == &item)
            items->push_back(std::move(item));
        else
            items->push_back(v);
    }
    checkTupleSize(*items);
    scratch = Value(Tuple(std::move(items)));
    return scratch;
}

const Value& format(const Program& p, const Node& n, const EvaluationFrame& frame, Value& scratch) {
    std::string text;
    for (int i = 0; i < n.count; ++i) {
        Value part;
        appendValueText(text, evaluateNode(p, p.lists[std::size_t(n.a + i)], frame, part));
        checkStringSize(text.size());
    }
    scratch = Value(std::move(text));
    return scratch;
}

double vectorComponent(const Value& v, bool x) {
    if (const Vec2* p = v.asVec()) return x ? p->x : p->y;
    throw EvaluationError(std::string("'.") + (x ? "x" : "y") + "' needs a Vec, got '" + typeName(v) + "'");
}

}  // namespace evaluate_detail

const Value& evaluateNode(const CompiledExpression::Program& p, std::int32_t index, const EvaluationFrame& frame,
                          Value& scratch) {
    using namespace evaluate_detail;
    const Node& n = p.nodes[std::size_t(index)];
    switch (n.op) {
        case Op::Constant: return p.constants[std::size_t(n.a)];
        case Op::Slot:
            if (std::size_t(n.a) >= frame.slotCount) throw EvaluationError("a name's slot is not bound in this frame");
            return frame.slots[n.a];
        case Op::Negate:
        case Op::Plus:
        case Op::Not: {
            Value t;
            const Value& v = evaluateNode(p, n.a, frame, t);
            if (n.op == Op::Not)
                scratch = Value(!truthy(v));
            else if (n.op == Op::Negate)
                negateValue(v, scratch);
            else
                plusValue(v, scratch);
            return scratch;
        }
        case Op::Binary: {
            Value ta, tb;
            const Value& a = evaluateNode(p, n.a, frame, ta);
            const Value& b = evaluateNode(p, n.b, frame, tb);
            binaryOperation(BinaryOp(n.sub), a, b, scratch);
            return scratch;
        }
        case Op::And:
        case Op::Or: {
            const Value& a = evaluateNode(p, n.a, frame, scratch);
            if (truthy(a) == (n.op == Op::Or)) return a;
            return evaluateNode(p, n.b, frame, scratch);
        }
        case Op::Compare: scratch = Value(compareChain(p, n, frame)); return scratch;
        case Op::IfElse: {
            Value t;
            const bool c = truthy(evaluateNode(p, n.a, frame, t));
            return evaluateNode(p, c ? n.b : n.c, frame, scratch);
        }
        case Op::Tuple: return buildTuple(p, n, frame, scratch);
        case Op::Attribute: {
            Value t;
            return attributeOf(evaluateNode(p, n.a, frame, t), n, frame);
        }
        case Op::VecX:
        case Op::VecY: {
            Value t;
            const double d = vectorComponent(evaluateNode(p, n.a, frame, t), n.op == Op::VecX);
            scratch = Value(d);
            return scratch;
        }
        case Op::Index: {
            Value ts, ti;
            const Value& seq = evaluateNode(p, n.a, frame, ts);
            const Value& i = evaluateNode(p, n.b, frame, ti);
            Value result;
            indexInto(seq, i, result);
            scratch = std::move(result);
            return scratch;
        }
        case Op::Call: return call(p, n, frame, scratch);
        case Op::Format: return format(p, n, frame, scratch);
    }
    throw EvaluationError("corrupt expression program");
}

CompiledExpression::CompiledExpression() = default;
CompiledExpression::~CompiledExpression() = default;
CompiledExpression::CompiledExpression(CompiledExpression&&) noexcept = default;
CompiledExpression& CompiledExpression::operator=(CompiledExpression&&) noexcept = default;
CompiledExpression::CompiledExpression(std::unique_ptr<Program> program) : program_(std::move(program)) {}

Value CompiledExpression::evaluate(const EvaluationFrame& frame) const {
    if (!program_) throw EvaluationError("evaluating an empty expression");
    Value scratch;
    const Value& v = evaluateNode(*program_, program_->root, frame, scratch);
    if (&v == &scratch) return scratch;
    return v;
}

bool CompiledExpression::isConstant() const { return program_ && program_->slots.empty() && !program_->random; }
bool CompiledExpression::drawsRandomly() const { return program_ && program_->random; }
const std::vector<int>& CompiledExpression::slotsRead() const {
    static const std::vector<int> kNone;
    return program_ ? program_->slots : kNone;
}

}  // namespace shapevo::graph
