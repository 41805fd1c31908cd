// Expression compiler: parses an arithmetic expression over parameters, attrs and the scope,
// type-checks it (scalar or 3-vector) and emits one stack program per component.
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "grammar/grammar.hpp"
#include "grammar/lexer.hpp"

namespace shapevo {

/// A name an expression can use besides parameters and attrs: a rule argument or a `let`
/// value. Constant ones (arguments known when the grammar is read) are folded into the code;
/// the others are read from the derivation's frame at parameter-block index `index`.
struct Binding {
    std::string name;
    int dims = 1;
    bool constant = true;
    float value[3] = {0, 0, 0};
    std::uint16_t index = 0;  ///< not constant: frame index of its first float
};

/// What an expression may refer to besides numbers and the scope.
struct ExpressionContext {
    const std::vector<Param>* params = nullptr;            ///< the current rule's parameters
    const std::map<std::string, double>* attrs = nullptr;  ///< grammar-wide constants
    const std::vector<Binding>* bindings = nullptr;        ///< arguments and lets (searched first)
    bool allowScope = true;  ///< false where only constants may appear (attrs, priors)
    const char* constantPlace = nullptr;  ///< for the error when !allowScope ("an attr value")
};

/// Largest evaluation stack an expression may need; deeper expressions are a located error.
inline constexpr int kMaxExpressionStack = 32;
/// Deepest nesting of parentheses, function calls and unary minus the parser accepts (bounds
/// its recursion, so hostile input cannot overflow the C++ stack).
inline constexpr int kMaxExpressionNesting = 64;
/// Most nodes (numbers, names, operators, calls) one expression may have.
inline constexpr int kMaxExpressionNodes = 4096;

/// True for names an expression gives a meaning of its own (scope, parent, pi and the
/// functions), which therefore cannot name a parameter or an attr. The vector functions
/// length, dot and distance (and `piece`) are not reserved: they mean themselves only where no
/// parameter, argument, let value or attr of that name is visible (`length(` always calls).
bool isReservedName(const std::string& name);

class ExpressionCompiler {
public:
    explicit ExpressionCompiler(TokenStream& tokens) : tokens_(tokens) {}

    /// Parse one expression and append its program(s) to `code`. `dims` is 1 or 3; a scalar
    /// expression is broadcast where 3 components are wanted, a vector where 1 is wanted is an error.
    void compile(const ExpressionContext& ctx, int dims, std::vector<Instr>& code, ExprRef out[3], int& maxStack);
    /// Dimension (1 or 3) of the last compiled expression, before any broadcast.
    int lastDims() const { return lastDims_; }
    /// How many times the expressions compiled so far read scope.origin or scope.axis (the
    /// parser puts a StatementKind::ScopeFrame before each statement that does).
    int scopeFrameReads() const { return scopeFrameReads_; }
    /// How many times the expressions compiled so far read piece.index or piece.count.
    int piecePlaceReads() const { return piecePlaceReads_; }
    /// The grammar's carried attributes (read by name, after parameters, arguments, lets and attrs).
    void setCarried(const std::vector<std::string>* names) { carried_ = names; }

private:
    const std::vector<std::string>* carried_ = nullptr;
    struct Node {
        enum Kind { Number, ParamRef, ScopeSize, ParentSize, Vector, Negate, Binary, Call, Swizzle, Not } kind;
        explicit Node(Kind k) : kind(k) {}
        int dims = 1;
        float value = 0;
        int first = 0;  ///< ParamRef: first float; Swizzle: component
        char op = 0;    ///< Binary: + - * / < l(<=) > g(>=) = (==) ! (!=) & (&&) | (||); Call: function letter
        int child[3] = {-1, -1, -1};
        SourceLocation where;
    };
    /// A Binary node `left op right` (a vector if either side is).
    int binary(char op, int left, int right, const SourceLocation& where);
    int parseOr();
    int parseAnd();
    int parseComparison();
    int parseSum();
    int parseProduct();
    int parseUnary();
    int parsePostfix();
    int parsePrimary();
    int parseIdentifier(const Token& t);
    int add(Node n);
    /// Enter one nesting level at `at` (fails beyond kMaxExpressionNesting); leave with --depth_.
    void enter(const SourceLocation& at);
    /// `scope.FIELD...` after `scope` (size, origin, axis.x / .y / .z).
    int parseScopeField(const Token& t);
    /// `piece.index` or `piece.count` after `piece`.
    int parsePieceField(const Token& t);
    /// The located error for a run-time value `what` in a constant place.
    [[noreturn]] void failConstantPlace(const SourceLocation& at, const std::string& what) const;
    void emit(int node, int component, std::vector<Instr>& code) const;

    TokenStream& tokens_;
    const ExpressionContext* ctx_ = nullptr;
    std::vector<Node> nodes_;
    int depth_ = 0;
    SourceLocation start_;
    int lastDims_ = 1;
    int scopeFrameReads_ = 0;
    int piecePlaceReads_ = 0;
};

/// True if the compiled scalar expression reads nothing but constants (so it can be folded).
bool isConstantExpression(const std::vector<Instr>& code, const ExprRef& e);

/// Fill in `e`'s small shape (ExprRef::Shape) from its instructions in `code`, or leave it a
/// Program when it has none of the small shapes.
void classifyExpression(const std::vector<Instr>& code, ExprRef& e);

/// Evaluate a compiled scalar expression with the stack machine: instructions [e.begin, e.end)
/// of `code` (a grammar's, or ones being compiled). `stack` must hold kMaxExpressionStack floats.
float evaluateProgram(const std::vector<Instr>& code, const ExprRef& e, const float* params, const float* scopeSize,
                      const float* parentSize, float* stack);
inline float evaluateProgram(const Grammar& g, const ExprRef& e, const float* params, const float* scopeSize,
                             const float* parentSize, float* stack) {
    return evaluateProgram(g.code, e, params, scopeSize, parentSize, stack);
}
/// The value of an expression that reads only constants (isConstantExpression), folded while the
/// grammar is read.
float evaluateConstant(const std::vector<Instr>& code, const ExprRef& e);

/// OpCode::Fresh away from the first piece of its kind: a value in [0, 1) that depends on every
/// bit of `u` and of the piece key `key` (murmur3's finalizer), so pieces draw independently.
float freshDraw(float u, std::uint32_t key);
/// The piece key of a piece: its parent task's key for the first piece of its kind
/// (`repetition` 0), else a hash of the parent key, the kind (Piece::first) and the repetition
/// (never 0). Keys start at 0 for the root.
std::uint32_t pieceKey(std::uint32_t parent, std::uint32_t kind, std::uint32_t repetition);

/// One binary operation exactly as the stack machine does it.
inline float applyBinary(OpCode op, float a, float b) {
    switch (op) {
    case OpCode::Add: return a + b;
    case OpCode::Sub: return a - b;
    case OpCode::Mul: return a * b;
    case OpCode::Div: return a / b;
    case OpCode::Min: return std::min(a, b);
    default: return std::max(a, b);  // Max: classifyExpression admits no other binary operation
    }
}

/// Evaluate a compiled scalar expression. `params` is the gene's parameter block; `stack` must
/// hold kMaxExpressionStack floats. Small shapes skip the stack machine (same bits).
[[gnu::always_inline]] inline float evaluate(const Grammar& g, const ExprRef& e, const float* params, const float* scopeSize,
                      const float* parentSize, float* stack) {
    if (e.shape == ExprRef::Shape::Program) return evaluateProgram(g, e, params, scopeSize, parentSize, stack);
    const float* const base[4] = {e.value, params, scopeSize, parentSize};  // indexed by LeafSource
    const float a = base[int(e.source[0])][e.index[0]];
    if (e.shape == ExprRef::Shape::Leaf) return a;
    const float b = base[int(e.source[1])][e.index[1]];
    if (e.shape == ExprRef::Shape::Binary) return applyBinary(e.op[0], a, b);
    const float c = base[int(e.source[2])][e.index[2]];
    if (e.shape == ExprRef::Shape::LeftNested) return applyBinary(e.op[1], applyBinary(e.op[0], a, b), c);
    return applyBinary(e.op[1], a, applyBinary(e.op[0], b, c));  // RightNested
}

}  // namespace shapevo
