// Expression compiler and evaluator: text -> typed tree -> per-component stack programs.
#include "grammar/expression.hpp"

#include <cmath>
#include <cstring>

namespace shapevo {

namespace {
struct Function {
    const char* name;
    char id;
    int arity;
    OpCode op;    ///< componentwise functions: the operation (vector functions compile their own)
    bool vector;  ///< length, dot, distance: 3-vector arguments, a scalar result; not reserved names
};
constexpr Function kFunctions[] = {
    {"min", 'm', 2, OpCode::Min, false}, {"max", 'M', 2, OpCode::Max, false},   {"abs", 'a', 1, OpCode::Abs, false},
    {"sin", 's', 1, OpCode::Sin, false}, {"cos", 'c', 1, OpCode::Cos, false},   {"sqrt", 'q', 1, OpCode::Sqrt, false},
    {"floor", 'f', 1, OpCode::Floor, false}, {"atan2", 't', 2, OpCode::Atan2, false},
    {"length", 'L', 1, OpCode::Sqrt, true}, {"dot", 'D', 2, OpCode::Add, true}, {"distance", 'G', 2, OpCode::Sqrt, true},
};
const Function* findFunction(const std::string& name) {
    for (const auto& f : kFunctions)
        if (name == f.name) return &f;
    return nullptr;
}
const Function* functionById(char id) {
    for (const auto& f : kFunctions)
        if (f.id == id) return &f;
    return nullptr;
}
int axisOf(const std::string& s) { return s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1; }
}  // namespace

bool isReservedName(const std::string& name) {
    const Function* f = findFunction(name);
    return name == "scope" || name == "parent" || name == "pi" || (f != nullptr && !f->vector);
}

int ExpressionCompiler::add(Node n) {
    if (int(nodes_.size()) >= kMaxExpressionNodes)
        tokens_.fail(start_, "expression is too long (more than " + std::to_string(kMaxExpressionNodes) +
                                 " numbers, names and operators)");
    nodes_.push_back(n);
    return int(nodes_.size()) - 1;
}

void ExpressionCompiler::enter(const SourceLocation& at) {
    if (++depth_ > kMaxExpressionNesting)
        tokens_.fail(at, "expression is nested too deeply (more than " + std::to_string(kMaxExpressionNesting) +
                             " levels of parentheses, function calls or unary minus)");
}

void ExpressionCompiler::compile(const ExpressionContext& ctx, int dims, std::vector<Instr>& code, ExprRef out[3],
                                 int& maxStack) {
    ctx_ = &ctx;
    nodes_.clear();
    depth_ = 0;
    const SourceLocation at = tokens_.peek().where;
    start_ = at;
    const int root = parseOr();
    lastDims_ = nodes_[root].dims;
    if (nodes_[root].dims == 3 && dims == 1)
        tokens_.fail(at, "expected a scalar expression here, but this expression is a 3-vector (use .x, .y or .z)");
    for (int c = 0; c < dims; ++c) {
        out[c].begin = std::uint32_t(code.size());
        emit(root, c, code);
        out[c].end = std::uint32_t(code.size());
        classifyExpression(code, out[c]);
        int depth = 0, deepest = 0;
        for (std::uint32_t i = out[c].begin; i < out[c].end; ++i) {
            switch (code[i].op) {
            case OpCode::Const: case OpCode::Param: case OpCode::ScopeSize: case OpCode::ParentSize: ++depth; break;
            case OpCode::Add: case OpCode::Sub: case OpCode::Mul: case OpCode::Div: case OpCode::Min: case OpCode::Max:
            case OpCode::Lt: case OpCode::Le: case OpCode::Gt: case OpCode::Ge: case OpCode::Eq: case OpCode::Ne:
            case OpCode::And: case OpCode::Or: case OpCode::Atan2:
                --depth;
                break;
            default: break;
            }
            deepest = std::max(deepest, depth);
        }
        if (deepest > kMaxExpressionStack)
            tokens_.fail(at, "expression is too deeply nested (needs a stack of " + std::to_string(deepest) +
                                 ", the limit is " + std::to_string(kMaxExpressionStack) + ")");
        maxStack = std::max(maxStack, deepest);
    }
}

int ExpressionCompiler::binary(char op, int left, int right, const SourceLocation& where) {
    Node n{Node::Binary};
    n.op = op;
    n.child[0] = left;
    n.child[1] = right;
    n.dims = std::max(nodes_[left].dims, nodes_[right].dims);
    n.where = where;
    return add(n);
}

int ExpressionCompiler::parseOr() {
    int left = parseAnd();
    while (tokens_.peek().is("||")) {
        const Token op = tokens_.take();
        left = binary('|', left, parseAnd(), op.where);
    }
    return left;
}

int ExpressionCompiler::parseAnd() {
    int left = parseComparison();
    while (tokens_.peek().is("&&")) {
        const Token op = tokens_.take();
        left = binary('&', left, parseComparison(), op.where);
    }
    return left;
}

int ExpressionCompiler::parseComparison() {
    int left = parseSum();
    const Token& t = tokens_.peek();
    char op = t.is('<') ? '<' : t.is('>') ? '>' : t.is("<=") ? 'l' : t.is(">=") ? 'g' : t.is("==") ? '=' : t.is("!=") ? '!' : 0;
    if (op == 0) return left;
    const Token opToken = tokens_.take();
    left = binary(op, left, parseSum(), opToken.where);
    const Token& next = tokens_.peek();
    if (next.is('<') || next.is('>') || next.is("<=") || next.is(">=") || next.is("==") || next.is("!="))
        tokens_.fail(next.where, "comparisons do not chain (write a < b && b < c)");
    return left;
}

int ExpressionCompiler::parseSum() {
    int left = parseProduct();
    while (tokens_.peek().is('+') || tokens_.peek().is('-')) {
        const Token op = tokens_.take();
        left = binary(op.text[0], left, parseProduct(), op.where);
    }
    return left;
}

int ExpressionCompiler::parseProduct() {
    int left = parseUnary();
    while (tokens_.peek().is('*') || tokens_.peek().is('/')) {
        const Token op = tokens_.take();
        left = binary(op.text[0], left, parseUnary(), op.where);
    }
    return left;
}

int ExpressionCompiler::parseUnary() {
    if (tokens_.peek().is('!')) {
        Token op = tokens_.take();
        enter(op.where);
        int inner = parseUnary();
        --depth_;
        Node n{Node::Not};
        n.child[0] = inner;
        n.dims = nodes_[inner].dims;
        n.where = op.where;
        return add(n);
    }
    if (tokens_.peek().is('-')) {
        Token op = tokens_.take();
        enter(op.where);
        int inner = parseUnary();
        --depth_;
        Node n{Node::Negate};
        n.child[0] = inner;
        n.dims = nodes_[inner].dims;
        n.where = op.where;
        return add(n);
    }
    return parsePostfix();
}

int ExpressionCompiler::parsePostfix() {
    int node = parsePrimary();
    while (tokens_.peek().is('.')) {
        tokens_.take();
        const SourceLocation at = tokens_.peek().where;
        const std::string comp = tokens_.expectIdentifier("a component x, y or z after '.'");
        const int axis = axisOf(comp);
        if (axis < 0) tokens_.fail(at, "expected a component x, y or z after '.', found '" + comp + "'");
        if (nodes_[node].dims != 3) tokens_.fail(at, "'." + comp + "' applies to a 3-vector, but this is a scalar");
        Node n{Node::Swizzle};
        n.first = axis;
        n.child[0] = node;
        n.where = at;
        node = add(n);
    }
    return node;
}

int ExpressionCompiler::parsePrimary() {
    const Token& t = tokens_.peek();
    if (t.kind == TokenKind::Number) {
        Node n{Node::Number};
        n.value = float(t.number);
        n.where = t.where;
        tokens_.take();
        return add(n);
    }
    if (t.is('(')) {
        const SourceLocation at = tokens_.take().where;
        enter(at);
        int first = parseOr();
        if (tokens_.peek().is(',')) {
            Node v{Node::Vector};
            v.dims = 3;
            v.where = at;
            v.child[0] = first;
            for (int c = 1; c < 3; ++c) {
                tokens_.expect(',', "between the components of a vector (x, y, z)");
                v.child[c] = parseOr();
            }
            for (int c = 0; c < 3; ++c)
                if (nodes_[v.child[c]].dims != 1)
                    tokens_.fail(nodes_[v.child[c]].where, "a vector component must be a scalar");
            tokens_.expect(')', "to close the vector");
            --depth_;
            return add(v);
        }
        tokens_.expect(')', "to close the parenthesis");
        --depth_;
        return first;
    }
    if (t.kind == TokenKind::Identifier) {
        Token id = tokens_.take();
        return parseIdentifier(id);
    }
    tokens_.expected("an expression (a number, a parameter, scope.size, parent.size, a function or '(')");
}

int ExpressionCompiler::parseIdentifier(const Token& t) {
    if (const Function* f = findFunction(t.text); f && (!f->vector || tokens_.peek().is('('))) {
        enter(t.where);
        tokens_.expect('(', "after function " + t.text);
        Node n{Node::Call};
        n.op = f->id;
        n.where = t.where;
        for (int a = 0; a < f->arity; ++a) {
            if (a > 0) tokens_.expect(',', "between the arguments of " + t.text);
            n.child[a] = parseOr();
            n.dims = std::max(n.dims, nodes_[n.child[a]].dims);
            if (f->vector && nodes_[n.child[a]].dims != 3)
                tokens_.fail(nodes_[n.child[a]].where, t.text + " takes 3-vectors (such as scope.origin or (x, y, z)), "
                                                                "but this argument is a scalar");
        }
        tokens_.expect(')', "after the " + std::to_string(f->arity) + " argument(s) of " + t.text);
        --depth_;
        if (f->vector) n.dims = 1;
        return add(n);
    }
    if (ctx_->bindings) {
        for (auto b = ctx_->bindings->rbegin(); b != ctx_->bindings->rend(); ++b) {
            if (b->name != t.text) continue;
            if (b->constant) {
                if (b->dims == 1) {
                    Node n{Node::Number};
                    n.value = b->value[0];
                    n.where = t.where;
                    return add(n);
                }
                Node v{Node::Vector};
                v.dims = 3;
                v.where = t.where;
                for (int c = 0; c < 3; ++c) {
                    Node n{Node::Number};
                    n.value = b->value[c];
                    n.where = t.where;
                    v.child[c] = add(n);
                }
                return add(v);
            }
            if (!ctx_->allowScope)
                tokens_.fail(t.where, std::string(ctx_->constantPlace ? ctx_->constantPlace : "this value") +
                                          " must be known when the grammar is read, but '" + t.text +
                                          "' is only known during a derivation");
            Node n{Node::ParamRef};
            n.first = b->index;
            n.dims = b->dims;
            n.where = t.where;
            return add(n);
        }
    }
    if (t.text == "scope") return parseScopeField(t);
    if (t.text == "parent") {
        if (!ctx_->allowScope) failConstantPlace(t.where, "parent.size");
        tokens_.expect('.', "after '" + t.text + "' (only " + t.text + ".size is available)");
        const SourceLocation at = tokens_.peek().where;
        const std::string field = tokens_.expectIdentifier("'size' after '" + t.text + ".'");
        if (field != "size") tokens_.fail(at, "expected 'size' after '" + t.text + ".', found '" + field + "'");
        Node n{t.text == "scope" ? Node::ScopeSize : Node::ParentSize};
        n.dims = 3;
        n.where = t.where;
        return add(n);
    }
    if (t.text == "pi") {
        Node n{Node::Number};
        n.value = float(M_PI);
        n.where = t.where;
        return add(n);
    }
    static const std::vector<Param> none;
    for (const Param& p : ctx_->params ? *ctx_->params : none) {
        if (p.name == t.text) {
            if (!ctx_->allowScope)
                tokens_.fail(t.where, std::string(ctx_->constantPlace ? ctx_->constantPlace : "this value") +
                                          " must be known when the grammar is read, so it cannot use parameter '" +
                                          t.text + "'");
            Node n{Node::ParamRef};
            n.first = p.first;
            n.dims = p.dims;
            n.where = t.where;
            return add(n);
        }
    }
    if (auto it = ctx_->attrs ? ctx_->attrs->find(t.text) : std::map<std::string, double>::const_iterator{};
        ctx_->attrs && it != ctx_->attrs->end()) {
        Node n{Node::Number};
        n.value = float(it->second);
        n.where = t.where;
        return add(n);
    }
    if (t.text == "piece" && tokens_.peek().is('.')) return parsePieceField(t);
    for (std::size_t k = 0; carried_ && k < carried_->size(); ++k)
        if ((*carried_)[k] == t.text) {
            if (!ctx_->allowScope) failConstantPlace(t.where, "carried attribute '" + t.text + "'");
            Node n{Node::ParamRef};
            n.first = kCarriedSlot + int(k);
            n.where = t.where;
            return add(n);
        }
    tokens_.fail(t.where, "unknown name '" + t.text +
                              "': expected a parameter declared above in this rule, an argument of the rule, "
                              "a let value, an attr, a carried attribute, scope.size, scope.origin, scope.axis.x (.y, .z), "
                              "parent.size, piece.index, piece.count, pi, or a function "
                              "(min max abs sin cos sqrt floor atan2 length dot distance)");
}

void ExpressionCompiler::failConstantPlace(const SourceLocation& at, const std::string& what) const {
    tokens_.fail(at, std::string(ctx_->constantPlace ? ctx_->constantPlace : "this value") +
                         " must be known when the grammar is read, so it cannot use " + what);
}

int ExpressionCompiler::parseScopeField(const Token& t) {
    const Token& next = tokens_.peekSecond();
    const std::string field = tokens_.peek().is('.') && next.kind == TokenKind::Identifier ? next.text : "size";
    if (!ctx_->allowScope) failConstantPlace(t.where, "scope." + field);
    tokens_.expect('.', "after 'scope' (scope.size, scope.origin or scope.axis.x, .y, .z)");
    const SourceLocation at = tokens_.peek().where;
    tokens_.expectIdentifier("'size', 'origin' or 'axis' after 'scope.'");
    Node n{Node::ScopeSize};
    n.dims = 3;
    n.where = t.where;
    if (field == "size") return add(n);
    if (field == "origin") {
        n.kind = Node::ParamRef;
        n.first = kScopeOriginSlot;
    } else if (field == "axis") {
        tokens_.expect('.', "after 'scope.axis' (scope.axis.x, .y or .z: the scope's world axes)");
        const SourceLocation axisAt = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("an axis x, y or z after 'scope.axis.'");
        const int axis = axisOf(name);
        if (axis < 0) tokens_.fail(axisAt, "expected an axis x, y or z after 'scope.axis.', found '" + name + "'");
        n.kind = Node::ParamRef;
        n.first = kScopeAxisSlot + 3 * axis;
    } else {
        tokens_.fail(at, "expected 'size', 'origin' or 'axis' after 'scope.', found '" + field + "'");
    }
    ++scopeFrameReads_;
    return add(n);
}

int ExpressionCompiler::parsePieceField(const Token& t) {
    const Token& next = tokens_.peekSecond();
    const std::string field = next.kind == TokenKind::Identifier ? next.text : "index";
    if (!ctx_->allowScope) failConstantPlace(t.where, "piece." + field);
    tokens_.take();  // .
    const SourceLocation at = tokens_.peek().where;
    tokens_.expectIdentifier("'index' or 'count' after 'piece.'");
    if (field != "index" && field != "count")
        tokens_.fail(at, "expected 'index' or 'count' after 'piece.', found '" + field + "'");
    Node n{Node::ParamRef};
    n.first = field == "index" ? kPieceIndexSlot : kPieceCountSlot;
    n.where = t.where;
    ++piecePlaceReads_;
    return add(n);
}

void ExpressionCompiler::emit(int index, int c, std::vector<Instr>& code) const {
    const Node& n = nodes_[index];
    const int comp = n.dims == 3 ? c : 0;
    switch (n.kind) {
    case Node::Number: code.push_back({OpCode::Const, 0, 0, n.value}); break;
    case Node::ParamRef: code.push_back({OpCode::Param, 0, std::uint16_t(n.first + comp), 0}); break;
    case Node::ScopeSize: code.push_back({OpCode::ScopeSize, std::uint8_t(comp), 0, 0}); break;
    case Node::ParentSize: code.push_back({OpCode::ParentSize, std::uint8_t(comp), 0, 0}); break;
    case Node::Vector: emit(n.child[comp], 0, code); break;
    case Node::Swizzle: emit(n.child[0], n.first, code); break;
    case Node::Negate:
        emit(n.child[0], comp, code);
        code.push_back({OpCode::Neg});
        break;
    case Node::Binary: {
        emit(n.child[0], comp, code);
        emit(n.child[1], comp, code);
        OpCode op = OpCode::Div;
        switch (n.op) {
        case '+': op = OpCode::Add; break;
        case '-': op = OpCode::Sub; break;
        case '*': op = OpCode::Mul; break;
        case '<': op = OpCode::Lt; break;
        case 'l': op = OpCode::Le; break;
        case '>': op = OpCode::Gt; break;
        case 'g': op = OpCode::Ge; break;
        case '=': op = OpCode::Eq; break;
        case '!': op = OpCode::Ne; break;
        case '&': op = OpCode::And; break;
        case '|': op = OpCode::Or; break;
        default: break;
        }
        code.push_back({op});
        break;
    }
    case Node::Not:
        emit(n.child[0], comp, code);
        code.push_back({OpCode::Not});
        break;
    case Node::Call: {
        const Function* f = functionById(n.op);
        if (!f->vector) {
            for (int a = 0; a < f->arity; ++a) emit(n.child[a], comp, code);
            code.push_back({f->op});
            break;
        }
        // length: sqrt((x*x + y*y) + z*z); dot: (ax*bx + ay*by) + az*bz; distance: the length of a - b.
        // Each argument's component is emitted once (so nested calls do not grow exponentially).
        for (int k = 0; k < 3; ++k) {
            emit(n.child[0], k, code);
            if (n.op == 'L') {
                code.push_back({OpCode::Square});
            } else {
                emit(n.child[1], k, code);
                code.push_back({n.op == 'D' ? OpCode::Mul : OpCode::Sub});
                if (n.op == 'G') code.push_back({OpCode::Square});
            }
            if (k > 0) code.push_back({OpCode::Add});
        }
        if (n.op != 'D') code.push_back({OpCode::Sqrt});
        break;
    }
    }
}

void classifyExpression(const std::vector<Instr>& code, ExprRef& e) {
    e.shape = ExprRef::Shape::Program;
    // Postfix tokens: 'L' a leaf, 'o' a binary operation; a negated number folds into its leaf
    // (negation is exact, so -(v) and the number -v are the same bits).
    char pattern[6];
    int tokens = 0, leaves = 0, ops = 0;
    ExprRef f = e;
    for (std::uint32_t i = e.begin; i < e.end; ++i) {
        const Instr& in = code[i];
        if (tokens == 5) return;
        switch (in.op) {
        case OpCode::Const:
        case OpCode::Param:
        case OpCode::ScopeSize:
        case OpCode::ParentSize: {
            if (leaves == 3) return;
            const int k = leaves++;
            f.source[k] = in.op == OpCode::Const   ? LeafSource::Const
                          : in.op == OpCode::Param ? LeafSource::Param
                          : in.op == OpCode::ScopeSize ? LeafSource::ScopeSize
                                                       : LeafSource::ParentSize;
            f.index[k] = in.op == OpCode::Const ? std::uint16_t(k) : in.op == OpCode::Param ? in.index : in.component;
            f.value[k] = in.value;
            pattern[tokens++] = 'L';
            break;
        }
        case OpCode::Neg:
            if (tokens == 0 || pattern[tokens - 1] != 'L' || f.source[leaves - 1] != LeafSource::Const) return;
            f.value[leaves - 1] = -f.value[leaves - 1];
            break;
        case OpCode::Add: case OpCode::Sub: case OpCode::Mul: case OpCode::Div: case OpCode::Min: case OpCode::Max:
            if (ops == 2) return;
            f.op[ops++] = in.op;
            pattern[tokens++] = 'o';
            break;
        default: return;  // abs, sin, ...: the stack machine
        }
    }
    const std::string p(pattern, pattern + tokens);
    if (p == "L") f.shape = ExprRef::Shape::Leaf;
    else if (p == "LLo") f.shape = ExprRef::Shape::Binary;
    else if (p == "LLoLo") f.shape = ExprRef::Shape::LeftNested;
    else if (p == "LLLoo") f.shape = ExprRef::Shape::RightNested;
    else return;
    e = f;
}

namespace {
/// The standard normal's quantile: Acklam's rational approximation (relative error below 1.2e-9),
/// far more than the float it is rounded to needs; 0 and 1 give -inf and +inf.
double normalQuantile(double p) {
    if (!(p > 0.0)) return p == 0.0 ? -INFINITY : NAN;
    if (!(p < 1.0)) return p == 1.0 ? INFINITY : NAN;
    static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                   1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
    static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                   6.680131188771972e+01,  -1.328068155288572e+01};
    static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                   -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
    static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                   3.754408661907416e+00};
    const double low = 0.02425;
    if (p < low || p > 1.0 - low) {
        const double q = std::sqrt(-2.0 * std::log(p < low ? p : 1.0 - p));
        const double x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
                         ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
        return p < low ? x : -x;
    }
    const double q = p - 0.5, r = q * q;
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}
}  // namespace

float freshDraw(float u, std::uint32_t key) {
    std::uint32_t h;
    std::memcpy(&h, &u, sizeof h);
    h ^= key * 0x9E3779B9u;  // then murmur3's finalizer: every input bit reaches every output bit
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

std::uint32_t pieceKey(std::uint32_t parent, std::uint32_t kind, std::uint32_t repetition) {
    if (repetition == 0) return parent;
    std::uint32_t h = parent * 0x9E3779B9u + kind * 0x85EBCA6Bu + repetition * 0xC2B2AE35u + 0x27D4EB2Fu;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h == 0 ? 1u : h;  // 0 means "the first of its kind"
}

bool isConstantExpression(const std::vector<Instr>& code, const ExprRef& e) {
    for (std::uint32_t i = e.begin; i < e.end; ++i)
        if (code[i].op == OpCode::Param || code[i].op == OpCode::ScopeSize || code[i].op == OpCode::ParentSize ||
            code[i].op == OpCode::Fresh)
            return false;
    return true;
}

float evaluateConstant(const std::vector<Instr>& code, const ExprRef& e) {
    float stack[kMaxExpressionStack];
    return evaluateProgram(code, e, nullptr, nullptr, nullptr, stack);
}

float evaluateProgram(const std::vector<Instr>& code, const ExprRef& e, const float* params, const float* scopeSize,
                      const float* parentSize, float* stack) {
    int top = -1;
    for (std::uint32_t i = e.begin; i < e.end; ++i) {
        const Instr& in = code[i];
        switch (in.op) {
        case OpCode::Const: stack[++top] = in.value; break;
        case OpCode::Param: stack[++top] = params[in.index]; break;
        case OpCode::ScopeSize: stack[++top] = scopeSize[in.component]; break;
        case OpCode::ParentSize: stack[++top] = parentSize[in.component]; break;
        case OpCode::Add: stack[top - 1] += stack[top]; --top; break;
        case OpCode::Sub: stack[top - 1] -= stack[top]; --top; break;
        case OpCode::Mul: stack[top - 1] *= stack[top]; --top; break;
        case OpCode::Div: stack[top - 1] /= stack[top]; --top; break;
        case OpCode::Min: stack[top - 1] = std::min(stack[top - 1], stack[top]); --top; break;
        case OpCode::Max: stack[top - 1] = std::max(stack[top - 1], stack[top]); --top; break;
        case OpCode::Neg: stack[top] = -stack[top]; break;
        case OpCode::Abs: stack[top] = std::fabs(stack[top]); break;
        case OpCode::Sin: stack[top] = std::sin(stack[top]); break;
        case OpCode::Cos: stack[top] = std::cos(stack[top]); break;
        case OpCode::Sqrt: stack[top] = std::sqrt(stack[top]); break;
        case OpCode::Floor: stack[top] = std::floor(stack[top]); break;
        case OpCode::Lt: stack[top - 1] = stack[top - 1] < stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::Le: stack[top - 1] = stack[top - 1] <= stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::Gt: stack[top - 1] = stack[top - 1] > stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::Ge: stack[top - 1] = stack[top - 1] >= stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::Eq: stack[top - 1] = stack[top - 1] == stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::Ne: stack[top - 1] = stack[top - 1] != stack[top] ? 1.0f : 0.0f; --top; break;
        case OpCode::And: stack[top - 1] = (stack[top - 1] != 0.0f && stack[top] != 0.0f) ? 1.0f : 0.0f; --top; break;
        case OpCode::Or: stack[top - 1] = (stack[top - 1] != 0.0f || stack[top] != 0.0f) ? 1.0f : 0.0f; --top; break;
        case OpCode::Not: stack[top] = stack[top] == 0.0f ? 1.0f : 0.0f; break;
        case OpCode::NormalCdf: stack[top] = float(0.5 * std::erfc(-double(stack[top]) * M_SQRT1_2)); break;
        case OpCode::NormalQuantile: stack[top] = float(normalQuantile(double(stack[top]))); break;
        case OpCode::Atan2: stack[top - 1] = std::atan2(stack[top - 1], stack[top]); --top; break;
        case OpCode::Square: stack[top] *= stack[top]; break;
        case OpCode::Fresh: {
            std::uint32_t key;
            std::memcpy(&key, params + kPieceKeySlot, sizeof key);
            if (key != 0) stack[top] = freshDraw(stack[top], key);
            break;
        }
        }
    }
    return stack[0];
}

}  // namespace shapevo
