// Priors over run-time values: uniform(a, b), int(a, b) and normal(mu, s) in [lo, hi] whose
// arguments use the scope, parameters, lets or inline arguments. The gene stores u in [0, 1]
// (the parameter's genome prior, which the operators see); a frame value drawn from u where the
// parameter is declared is what the rule's expressions read (grammars/README.md gives the
// formulas). Constant priors never come here (parser.cpp folds them) unless marked `per piece`:
// then the draw reads OpCode::Fresh of u, so each piece of one statement gets its own value.
#include <cmath>

#include "grammar/parser_state.hpp"

namespace shapevo::grammar_detail {

namespace {
/// Largest evaluation stack the instructions [begin, end) need.
int stackDepth(const std::vector<Instr>& code, std::uint32_t begin, std::uint32_t end) {
    int depth = 0, deepest = 0;
    for (std::uint32_t i = begin; i < end; ++i) {
        switch (code[i].op) {
        case OpCode::Const: case OpCode::Param: case OpCode::ScopeSize: case OpCode::ParentSize: ++depth; break;
        case OpCode::Neg: case OpCode::Abs: case OpCode::Sin: case OpCode::Cos: case OpCode::Sqrt: case OpCode::Floor:
        case OpCode::Not: case OpCode::NormalCdf: case OpCode::NormalQuantile: case OpCode::Fresh: case OpCode::Square: break;
        default: --depth; break;  // the binary operations
        }
        deepest = std::max(deepest, depth);
    }
    return deepest;
}

/// The bounds of a run-time prior: compiled expressions in Grammar::code (mu and sigma: normal's).
struct DrawBounds {
    ExprRef lo, hi, mu, sigma;
};

/// Appends to `code` the draw of a `kind` prior (uniform, int or normal) with bounds `b` from the
/// stored u in [0, 1] (parameter float `u`; OpCode::Fresh of it when `perPiece`):
///   uniform(a, b): a + u (b - a)        int(a, b): min(floor(ceil(a) + u (floor(b) - ceil(a) + 1)), floor(b))
///   normal(mu, s) in [lo, hi]: min(hi, max(lo, mu + s Q(F(α) + u (F(β) − F(α))))) with
///   α = (lo − mu) / s, β = (hi − mu) / s, F the standard normal CDF and Q its inverse
void emitDraw(std::vector<Instr>& code, const std::string& kind, const DrawBounds& b, std::uint16_t u, bool perPiece) {
    const ExprRef &lo = b.lo, &hi = b.hi, &mu = b.mu, &sigma = b.sigma;
    auto pushU = [&] {
        code.push_back({OpCode::Param, 0, u, 0});
        if (perPiece) code.push_back({OpCode::Fresh});
    };
    auto copy = [&](const ExprRef& r) {
        const std::vector<Instr> part(code.begin() + r.begin, code.begin() + r.end);
        code.insert(code.end(), part.begin(), part.end());
    };
    if (kind == "normal") {
        auto standardCdf = [&](const ExprRef& bound) {
            copy(bound);
            copy(mu);
            code.push_back({OpCode::Sub});
            copy(sigma);
            code.push_back({OpCode::Div});
            code.push_back({OpCode::NormalCdf});
        };
        copy(hi);
        copy(lo);
        copy(mu);
        copy(sigma);
        standardCdf(lo);
        pushU();
        standardCdf(hi);
        standardCdf(lo);
        code.push_back({OpCode::Sub});
        code.push_back({OpCode::Mul});
        code.push_back({OpCode::Add});
        code.push_back({OpCode::NormalQuantile});
        code.push_back({OpCode::Mul});
        code.push_back({OpCode::Add});
        code.push_back({OpCode::Max});  // max(lo, v): a NaN draw becomes lo
        code.push_back({OpCode::Min});  // min(hi, .)
    } else if (kind == "uniform") {
        copy(lo);
        pushU();
        copy(hi);
        copy(lo);
        code.push_back({OpCode::Sub});
        code.push_back({OpCode::Mul});
        code.push_back({OpCode::Add});
    } else {
        auto ceilLo = [&] {
            copy(lo);
            code.push_back({OpCode::Neg});
            code.push_back({OpCode::Floor});
            code.push_back({OpCode::Neg});
        };
        auto floorHi = [&] {
            copy(hi);
            code.push_back({OpCode::Floor});
        };
        ceilLo();
        pushU();
        floorHi();
        ceilLo();
        code.push_back({OpCode::Sub});
        code.push_back({OpCode::Const, 0, 0, 1.0f});
        code.push_back({OpCode::Add});
        code.push_back({OpCode::Mul});
        code.push_back({OpCode::Add});
        code.push_back({OpCode::Floor});
        floorHi();
        code.push_back({OpCode::Min});
    }
}
}  // namespace

bool Parser::parseRunTimePrior(Rule& rule, BodyScope& scope, Param& p, const std::string& kind, const SourceLocation& at) {
    // Probe: do the two arguments depend on anything known only during a derivation?
    const std::size_t start = tokens_.mark();
    const ExpressionContext ctx{&scope.params, scope.attrs, &scope.bindings, true, nullptr};
    std::vector<Instr> probe;
    ExprRef e[3];
    int stack = 0;
    bool constant = true;
    for (int k = 0; k < 2; ++k) {
        if (k > 0) tokens_.expect(',', "between the two arguments of " + kind);
        const Token& t = tokens_.peek();
        if (t.kind == TokenKind::End || t.is(')') || t.is(',')) break;  // the constant path reports it
        exprs_.compile(ctx, 3, probe, e, stack);
        for (int c = 0; c < 3; ++c) constant = constant && isConstantExpression(probe, e[c]);
    }
    if (kind == "normal" && tokens_.peek().is(')')) {  // and its bounds: in [lo, hi]
        tokens_.take();
        if (tokens_.peek().isWord("in")) {
            tokens_.take();
            if (tokens_.peek().is('[')) {
                tokens_.take();
                for (int k = 0; k < 2; ++k) {
                    if (k > 0) {
                        if (!tokens_.peek().is(',')) break;
                        tokens_.take();
                    }
                    const Token& t = tokens_.peek();
                    if (t.kind == TokenKind::End || t.is(']') || t.is(',')) break;
                    exprs_.compile(ctx, 3, probe, e, stack);
                    for (int c = 0; c < 3; ++c) constant = constant && isConstantExpression(probe, e[c]);
                }
            }
        }
    }
    if (kind != "normal" && tokens_.peek().is(')')) tokens_.take();
    if (kind == "normal" && tokens_.peek().is(']')) tokens_.take();
    // `per piece`: every piece of a split, repeat, comp or lot draws its own value (OpCode::Fresh)
    const bool perPiece = tokens_.peek().isWord("per") && tokens_.peekSecond().isWord("piece");
    tokens_.seek(start);
    if (constant && !perPiece) return false;
    // A run-time prior: the gene stores u in [0, 1] (its genome prior); the value is drawn from u
    // where the parameter is declared (emitDraw), into a frame value the rule's expressions read.
    DrawBounds bounds;
    ExprRef &lo = bounds.lo, &hi = bounds.hi, &mu = bounds.mu, &sigma = bounds.sigma;
    const SourceLocation loAt = tokens_.peek().where;
    compileScalar(scope, kind == "normal" ? mu : lo);
    tokens_.expect(',', "between the two arguments of " + kind);
    compileScalar(scope, kind == "normal" ? sigma : hi);
    tokens_.expect(')', "after the two arguments of " + kind);
    if (kind == "normal") {
        if (!tokens_.peek().isWord("in")) tokens_.expected("'in [lo, hi]' after normal(mu, sigma): its support must be bounded");
        tokens_.take();
        tokens_.expect('[', "after 'in'");
        compileScalar(scope, lo);
        tokens_.expect(',', "between the bounds");
        compileScalar(scope, hi);
        tokens_.expect(']', "to close the bounds");
    }
    p.dims = 1;
    p.prior[0] = p.prior[1] = p.prior[2] = Prior{PriorKind::Uniform, 0.0f, 1.0f};
    p.first = rule.paramFloats;
    rule.paramFloats = std::uint16_t(rule.paramFloats + 1);
    if (rule.paramFloats > 256) tokens_.fail(at, "rule " + rule.name + " has more than 256 parameter values");
    const std::uint16_t u = p.first;
    std::vector<Instr>& code = g_.code;
    const auto begin = std::uint32_t(code.size());
    emitDraw(code, kind, bounds, u, perPiece);
    if (perPiece) {
        tokens_.take();  // per
        tokens_.take();  // piece
        g_.usesPieceKeys = true;
    }
    ExprRef value{begin, std::uint32_t(code.size())};
    const int depth = stackDepth(code, value.begin, value.end);
    if (depth > kMaxExpressionStack)
        tokens_.fail(loAt, "the bounds of this prior are too deeply nested (the draw needs a stack of " +
                               std::to_string(depth) + ", the limit is " + std::to_string(kMaxExpressionStack) + ")");
    g_.maxStack = std::max(g_.maxStack, depth);
    classifyExpression(code, value);
    scope.bindings.push_back(letValue(rule, p.name, 1, &value, at));
    Param stored = p;
    stored.name = scope.prefix + p.name;
    rule.params.push_back(stored);
    return true;
}

}  // namespace shapevo::grammar_detail
