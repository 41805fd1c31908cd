// The expression parser (internal to the expression files): tokens -> the flat Program of
// expression_program.hpp. One Parser per text range: compileExpression makes one for the whole
// text, and an f-string makes one per {field}, sharing the same ParseContext and nesting depth.
#pragma once
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "graph/expression_lexer.hpp"
#include "graph/expression_program.hpp"

namespace shapevo::graph {

struct ParseContext {
    CompiledExpression::Program* program;
    const NameSlots* slots;
    AttrNames* names;
    std::vector<int> treeDepth;  // per node: the depth of its subtree
};

class Parser {
public:
    /// Parses text[begin, end) at nesting depth `depth`.
    Parser(std::string_view text, std::size_t begin, std::size_t end, ParseContext& context, int depth);
    /// The whole range as one expression; returns its root node.
    std::int32_t parseAll();

private:
    [[noreturn]] void fail(const std::string& what, std::size_t offset) const;
    [[noreturn]] void unexpected(const Token& t) const;
    const Token& peek() const { return tokens_[next_]; }
    const Token& take() { return tokens_[next_++]; }
    bool isPunct(std::string_view p) const;
    bool isName(std::string_view n) const;
    void expectPunct(std::string_view p);
    void enter(std::size_t offset);

    std::int32_t add(Node node, std::initializer_list<std::int32_t> children);
    std::int32_t addWithDepth(Node node, int depth);
    std::int32_t addList(Op op, std::uint8_t sub, const std::vector<std::int32_t>& items, std::size_t offset);
    std::int32_t constant(Value v, std::size_t offset);

    std::int32_t parseExpression();
    std::int32_t parseOr();
    std::int32_t parseAnd();
    std::int32_t parseNot();
    bool comparisonOperator(CompareOp& op) const;
    std::int32_t parseComparison();
    std::int32_t parseArithmetic();
    std::int32_t parseTerm();
    std::int32_t parseUnary();
    std::int32_t parsePostfix();
    std::int32_t parseSubscript(std::int32_t target, bool attrOnly);
    std::int32_t parseAtom();
    std::int32_t parseParenthesised();
    std::int32_t parseName();
    std::int32_t parseCall(const std::string& name, std::size_t at);
    std::int32_t vecCall(std::vector<std::int32_t>& args, const std::vector<std::string_view>& keywords, std::size_t at);
    /// Adjacent string and f-string literals, concatenated (expression_fstring.cpp).
    std::int32_t parseStrings();
    void fstringParts(const Token& t, std::string& literal, std::vector<std::int32_t>& parts);

    std::string_view text_;
    std::vector<Token> tokens_;
    std::size_t next_ = 0;
    ParseContext& context_;
    int depth_;
};

}  // namespace shapevo::graph
