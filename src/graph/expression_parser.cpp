// compileExpression (expression.hpp): a recursive-descent parser over Python's precedence
// (conditional, or, and, not, comparisons, + -, * / // %, unary, postfix, atoms) that builds the
// flat Program of expression_program.hpp. Every name is resolved here: a slot, True/False/None,
// pi / math.pi / np.pi, or a whitelisted function (expression_functions.cpp); anything else is an
// ExpressionError naming the token at its byte offset. Depth is checked before each recursion.
// f-strings are split in expression_fstring.cpp.
#include "graph/expression_parser.hpp"

#include <algorithm>
#include <cmath>

#include "graph/expression_functions.hpp"

namespace shapevo::graph {
namespace parser_detail {

constexpr std::string_view kKeywords[] = {"and", "as", "assert", "async", "await", "break", "class", "continue",
                                          "def", "del", "elif", "else", "except", "finally", "for", "from",
                                          "global", "if", "import", "in", "is", "lambda", "nonlocal", "not",
                                          "or", "pass", "raise", "return", "try", "while", "with", "yield"};

bool isKeyword(std::string_view name) {
    return std::find(std::begin(kKeywords), std::end(kKeywords), name) != std::end(kKeywords);
}

bool isDunder(std::string_view name) { return name.size() >= 2 && name.substr(0, 2) == "__"; }

}  // namespace parser_detail


Parser::Parser(std::string_view text, std::size_t begin, std::size_t end, ParseContext& context, int depth)
    : text_(text), tokens_(tokenize(text, begin, end)), context_(context), depth_(depth) {}

std::int32_t Parser::parseAll() {
    const std::int32_t root = parseExpression();
    if (peek().kind != TokenKind::End) {
        if (isPunct(",")) fail("a top-level tuple needs parentheses", peek().offset);
        unexpected(peek());
    }
    return root;
}

void Parser::fail(const std::string& what, std::size_t offset) const { throw ExpressionError(what, offset); }

void Parser::unexpected(const Token& t) const {
    if (t.kind == TokenKind::End) fail("unexpected end of expression", t.offset);
    if (t.kind == TokenKind::Punct) {
        const std::string_view p = t.text;
        if (p == "[") fail("list displays and comprehensions ('[') are not supported", t.offset);
        if (p == "{") fail("dict and set displays ('{') are not supported", t.offset);
        if (p == "**") fail("operator '**' is not supported", t.offset);
        if (p == "=" || p == ":=") fail("assignment ('" + std::string(p) + "') is not supported", t.offset);
    }
    if (t.kind == TokenKind::Name && parser_detail::isKeyword(t.text) && t.text != "not" && t.text != "and" && t.text != "or" &&
        t.text != "if" && t.text != "else")
        fail("'" + std::string(t.text) + "' is not supported", t.offset);
    fail("unexpected " + quoteForMessage(t.kind == TokenKind::FString ? std::string_view("f-string") : t.text),
         t.offset);
}

bool Parser::isPunct(std::string_view p) const { return peek().kind == TokenKind::Punct && peek().text == p; }
bool Parser::isName(std::string_view n) const { return peek().kind == TokenKind::Name && peek().text == n; }

void Parser::expectPunct(std::string_view p) {
    if (!isPunct(p)) {
        if (peek().kind == TokenKind::End) fail("expected '" + std::string(p) + "' before the end", peek().offset);
        fail("expected '" + std::string(p) + "', found " + quoteForMessage(peek().text), peek().offset);
    }
    ++next_;
}

void Parser::enter(std::size_t offset) {
    if (++depth_ > kMaxExpressionDepth)
        fail("expression nested deeper than " + std::to_string(kMaxExpressionDepth) + " levels", offset);
}

std::int32_t Parser::add(Node node, std::initializer_list<std::int32_t> children) {
    int depth = 1;
    for (const std::int32_t c : children) depth = std::max(depth, context_.treeDepth[std::size_t(c)] + 1);
    return addWithDepth(node, depth);
}

std::int32_t Parser::addWithDepth(Node node, int depth) {
    if (depth > kMaxExpressionTreeDepth)
        fail("expression too deep: more than " + std::to_string(kMaxExpressionTreeDepth) + " chained operations", node.offset);
    auto& p = *context_.program;
    p.nodes.push_back(node);
    context_.treeDepth.push_back(depth);
    return std::int32_t(p.nodes.size() - 1);
}

std::int32_t Parser::addList(Op op, std::uint8_t sub, const std::vector<std::int32_t>& items, std::size_t offset) {
    if (items.size() > 0xffff) fail("too many operands (over 65535)", offset);
    auto& p = *context_.program;
    Node n{op, sub, std::uint16_t(items.size()), std::int32_t(p.lists.size()), 0, 0, std::uint32_t(offset)};
    int depth = 1;
    for (const std::int32_t c : items) {
        p.lists.push_back(c);
        depth = std::max(depth, context_.treeDepth[std::size_t(c)] + 1);
    }
    return addWithDepth(n, depth);
}

std::int32_t Parser::constant(Value v, std::size_t offset) {
    auto& p = *context_.program;
    p.constants.push_back(std::move(v));
    return add(Node{Op::Constant, 0, 0, std::int32_t(p.constants.size() - 1), 0, 0, std::uint32_t(offset)}, {});
}

// expression := or_test ['if' or_test 'else' expression]
std::int32_t Parser::parseExpression() {
    const std::size_t at = peek().offset;
    enter(at);
    if (isName("lambda")) fail("'lambda' is not supported", at);
    std::int32_t e = parseOr();
    if (isName("if")) {
        const std::size_t ifAt = peek().offset;
        ++next_;
        const std::int32_t cond = parseOr();
        if (!isName("else")) fail("expected 'else' after 'a if c'", peek().offset);
        ++next_;
        const std::int32_t other = parseExpression();
        e = add(Node{Op::IfElse, 0, 0, cond, e, other, std::uint32_t(ifAt)}, {cond, e, other});
    }
    --depth_;
    return e;
}

std::int32_t Parser::parseOr() {
    std::int32_t e = parseAnd();
    while (isName("or")) {
        const std::size_t at = take().offset;
        const std::int32_t r = parseAnd();
        e = add(Node{Op::Or, 0, 0, e, r, 0, std::uint32_t(at)}, {e, r});
    }
    return e;
}

std::int32_t Parser::parseAnd() {
    std::int32_t e = parseNot();
    while (isName("and")) {
        const std::size_t at = take().offset;
        const std::int32_t r = parseNot();
        e = add(Node{Op::And, 0, 0, e, r, 0, std::uint32_t(at)}, {e, r});
    }
    return e;
}

std::int32_t Parser::parseNot() {
    if (!isName("not")) return parseComparison();
    const std::size_t at = take().offset;
    enter(at);
    const std::int32_t operand = parseNot();
    --depth_;
    return add(Node{Op::Not, 0, 0, operand, 0, 0, std::uint32_t(at)}, {operand});
}

bool Parser::comparisonOperator(CompareOp& op) const {
    const Token& t = peek();
    if (t.kind == TokenKind::Name && (t.text == "in" || t.text == "is" || t.text == "not"))
        fail("operator '" + std::string(t.text) + "' is not supported", t.offset);
    if (t.kind != TokenKind::Punct) return false;
    static constexpr std::pair<std::string_view, CompareOp> kOps[] = {
        {"==", CompareOp::Eq}, {"!=", CompareOp::Ne}, {"<", CompareOp::Lt},
        {"<=", CompareOp::Le}, {">", CompareOp::Gt},  {">=", CompareOp::Ge}};
    for (const auto& [text, value] : kOps)
        if (t.text == text) return op = value, true;
    return false;
}

std::int32_t Parser::parseComparison() {
    const std::size_t at = peek().offset;
    std::int32_t first = parseArithmetic();
    CompareOp op{};
    if (!comparisonOperator(op)) return first;
    std::vector<std::int32_t> operands{first};
    std::vector<std::int32_t> ops;
    while (comparisonOperator(op)) {
        ++next_;
        ops.push_back(std::int32_t(op));
        operands.push_back(parseArithmetic());
    }
    // The list holds the operands, then the operators.
    std::vector<std::int32_t> items = operands;
    const std::int32_t node = addList(Op::Compare, 0, items, at);
    auto& p = *context_.program;
    p.lists.insert(p.lists.end(), ops.begin(), ops.end());
    return node;
}

std::int32_t Parser::parseArithmetic() {
    std::int32_t e = parseTerm();
    while (isPunct("+") || isPunct("-")) {
        const Token& t = take();
        const BinaryOp op = t.text == "+" ? BinaryOp::Add : BinaryOp::Sub;
        const std::int32_t r = parseTerm();
        e = add(Node{Op::Binary, std::uint8_t(op), 0, e, r, 0, t.offset}, {e, r});
    }
    return e;
}

std::int32_t Parser::parseTerm() {
    std::int32_t e = parseUnary();
    for (;;) {
        BinaryOp op;
        if (isPunct("*"))
            op = BinaryOp::Mul;
        else if (isPunct("/"))
            op = BinaryOp::Div;
        else if (isPunct("//"))
            op = BinaryOp::FloorDiv;
        else if (isPunct("%"))
            op = BinaryOp::Mod;
        else if (isPunct("@"))
            fail("operator '@' is not supported", peek().offset);
        else
            return e;
        const std::size_t at = take().offset;
        const std::int32_t r = parseUnary();
        e = add(Node{Op::Binary, std::uint8_t(op), 0, e, r, 0, std::uint32_t(at)}, {e, r});
    }
}

std::int32_t Parser::parseUnary() {
    if (isPunct("~")) fail("operator '~' is not supported", peek().offset);
    if (!isPunct("-") && !isPunct("+")) {
        const std::int32_t e = parsePostfix();
        if (isPunct("**")) fail("operator '**' is not supported", peek().offset);
        for (const std::string_view bad : {"<<", ">>", "&", "|", "^"})
            if (isPunct(bad)) fail("operator '" + std::string(bad) + "' is not supported", peek().offset);
        return e;
    }
    const Token& t = take();
    enter(t.offset);
    const Op op = t.text == "-" ? Op::Negate : Op::Plus;
    const std::int32_t operand = parseUnary();
    --depth_;
    return add(Node{op, 0, 0, operand, 0, 0, t.offset}, {operand});
}

std::int32_t Parser::parsePostfix() {
    std::int32_t e = parseAtom();
    for (;;) {
        if (isPunct(".")) {
            const std::size_t at = take().offset;
            if (peek().kind != TokenKind::Name) fail("expected a name after '.'", peek().offset);
            const Token& name = take();
            if (name.text == "x" || name.text == "y") {
                e = add(Node{name.text == "x" ? Op::VecX : Op::VecY, 0, 0, e, 0, 0, std::uint32_t(at)}, {e});
            } else if (name.text == "attr") {
                if (!isPunct("[")) fail("'.attr' must be followed by ['key']", peek().offset);
                e = parseSubscript(e, true);
            } else if (parser_detail::isDunder(name.text)) {
                fail("'." + std::string(name.text) + "': names starting with '__' are not allowed", name.offset);
            } else {
                fail("attribute '." + std::string(name.text) + "' is not allowed (only .attr['key'], .x and .y)",
                     name.offset);
            }
        } else if (isPunct("[")) {
            e = parseSubscript(e, false);
        } else if (isPunct("(")) {
            fail("only the whitelisted functions may be called", peek().offset);
        } else {
            return e;
        }
    }
}

// '[' 'key' ']' reads an attribute; '[' expression ']' indexes a tuple.
std::int32_t Parser::parseSubscript(std::int32_t target, bool attrOnly) {
    const std::size_t at = take().offset;
    if (peek().kind == TokenKind::String && tokens_[next_ + 1].kind == TokenKind::Punct &&
        tokens_[next_ + 1].text == "]") {
        const Token& key = take();
        ++next_;
        const AttrKey k = context_.names->intern(key.stringValue);
        return add(Node{Op::Attribute, 0, 0, target, std::int32_t(k), 0, std::uint32_t(at)}, {target});
    }
    if (attrOnly) fail("'.attr[...]' needs a quoted key, like .attr['name']", peek().offset);
    if (isPunct("]")) fail("an empty subscript '[]'", peek().offset);
    const std::int32_t index = parseExpression();
    if (isPunct(":")) fail("slices are not supported", peek().offset);
    expectPunct("]");
    return add(Node{Op::Index, 0, 0, target, index, 0, std::uint32_t(at)}, {target, index});
}

std::int32_t Parser::parseAtom() {
    const Token& t = peek();
    switch (t.kind) {
        case TokenKind::Int: ++next_; return constant(Value(t.intValue), t.offset);
        case TokenKind::Float: ++next_; return constant(Value(t.floatValue), t.offset);
        case TokenKind::String:
        case TokenKind::FString: return parseStrings();
        case TokenKind::Name: return parseName();
        case TokenKind::Punct:
            if (t.text == "(") return parseParenthesised();
            unexpected(t);
        default: unexpected(t);
    }
}

std::int32_t Parser::parseParenthesised() {
    const std::size_t at = take().offset;
    if (isPunct(")")) {
        ++next_;
        return constant(Value(Tuple(std::make_shared<const std::vector<Value>>())), at);
    }
    const std::int32_t first = parseExpression();
    if (isPunct(")")) {
        ++next_;
        return first;
    }
    if (!isPunct(",")) {
        if (isName("for")) fail("comprehensions ('for') are not supported", peek().offset);
        expectPunct(")");
    }
    std::vector<std::int32_t> items{first};
    while (isPunct(",")) {
        ++next_;
        if (isPunct(")")) break;
        items.push_back(parseExpression());
    }
    expectPunct(")");
    return addList(Op::Tuple, 0, items, at);
}

std::int32_t Parser::parseName() {
    const Token& t = take();
    const std::string_view name = t.text;
    if (name == "True") return constant(Value(true), t.offset);
    if (name == "False") return constant(Value(false), t.offset);
    if (name == "None") return constant(Value(), t.offset);
    if (parser_detail::isKeyword(name)) {
        --next_;
        unexpected(t);
    }
    if (parser_detail::isDunder(name)) fail("'" + std::string(name) + "': names starting with '__' are not allowed", t.offset);
    if ((name == "random" || name == "np" || name == "math") && isPunct(".")) {
        ++next_;
        if (peek().kind != TokenKind::Name) fail("expected a name after '" + std::string(name) + ".'", peek().offset);
        const std::string qualified = std::string(name) + "." + std::string(take().text);
        if (isPunct("(")) return parseCall(qualified, t.offset);
        if (qualified == "math.pi" || qualified == "np.pi") return constant(Value(M_PI), t.offset);
        fail("unknown name '" + qualified + "'", t.offset);
    }
    if (isPunct("(")) return parseCall(std::string(name), t.offset);
    const int slot = context_.slots->find(name);
    if (slot >= 0) {
        context_.program->slots.push_back(slot);
        return add(Node{Op::Slot, 0, 0, slot, 0, 0, t.offset}, {});
    }
    if (name == "pi") return constant(Value(M_PI), t.offset);
    if (name == "random" || name == "np" || name == "math")
        fail("'" + std::string(name) + "' may only prefix a whitelisted call", t.offset);
    fail("unknown name '" + std::string(name) + "'", t.offset);
}

std::int32_t Parser::parseCall(const std::string& name, std::size_t at) {
    ++next_;  // '('
    std::vector<std::int32_t> args;
    std::vector<std::string_view> keywords;
    while (!isPunct(")")) {
        if (peek().kind == TokenKind::Name && tokens_[next_ + 1].kind == TokenKind::Punct &&
            tokens_[next_ + 1].text == "=") {
            keywords.push_back(peek().text);
            next_ += 2;
        } else if (!keywords.empty()) {
            fail("a positional argument after a keyword argument", peek().offset);
        } else if (isPunct("*") || isPunct("**")) {
            fail("argument unpacking ('" + std::string(peek().text) + "') is not supported", peek().offset);
        }
        args.push_back(parseExpression());
        if (isName("for")) fail("comprehensions ('for') are not supported", peek().offset);
        if (!isPunct(",")) break;
        ++next_;
    }
    expectPunct(")");
    if (name == "Vec") return vecCall(args, keywords, at);
    const FunctionInfo* f = findFunction(name);
    if (!f) fail("unknown function '" + name + "'", at);
    if (!keywords.empty()) fail(name + "() takes no keyword arguments", at);
    const int n = int(args.size());
    if (n < f->minArgs || (f->maxArgs >= 0 && n > f->maxArgs)) {
        std::string expected = std::to_string(f->minArgs);
        if (f->maxArgs < 0)
            expected = "at least " + expected;
        else if (f->maxArgs != f->minArgs)
            expected += " to " + std::to_string(f->maxArgs);
        fail(name + "() takes " + expected + " argument" + (f->maxArgs == 1 && f->minArgs == 1 ? "" : "s") + " (" +
                 std::to_string(n) + " given)",
             at);
    }
    if (f->id == Function::RandomRandom || f->id == Function::RandomUniform || f->id == Function::RandomRandint ||
        f->id == Function::RandomChoice)
        context_.program->random = true;
    return addList(Op::Call, std::uint8_t(f->id), args, at);
}

std::int32_t Parser::vecCall(std::vector<std::int32_t>& args, const std::vector<std::string_view>& keywords,
                             std::size_t at) {
    const auto form = [&](std::string_view k1, std::string_view k2) {
        if (keywords.size() != 2) return false;
        if (keywords[0] == k1 && keywords[1] == k2) return true;
        if (keywords[0] == k2 && keywords[1] == k1) return std::swap(args[0], args[1]), true;
        return false;
    };
    Function f;
    if (keywords.empty() && args.size() == 1)
        f = Function::VecOf;
    else if (keywords.empty() && args.size() == 2)
        f = Function::VecFromTo;
    else if (form("x1", "y1"))
        f = Function::VecXY;
    else if (form("vec1", "vec2"))
        f = Function::VecFromTo;
    else
        fail("Vec takes (element), (a, b), (x1=, y1=) or (vec1=, vec2=)", at);
    return addList(Op::Call, std::uint8_t(f), args, at);
}

CompiledExpression compileExpression(std::string_view text, const NameSlots& slots, AttrNames& names) {
    if (text.size() > kMaxExpressionBytes)
        throw ExpressionError("expression longer than " + std::to_string(kMaxExpressionBytes) + " bytes", kMaxExpressionBytes);
    auto program = std::make_unique<CompiledExpression::Program>();
    ParseContext context{program.get(), &slots, &names, {}};
    Parser parser(text, 0, text.size(), context, 0);
    program->root = parser.parseAll();
    auto& s = program->slots;
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return CompiledExpression(std::move(program));
}

}  // namespace shapevo::graph
