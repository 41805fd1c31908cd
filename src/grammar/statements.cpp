// Rule bodies: statements, blocks (`terminal`, `if` / `case`), `let`, splits and repeats, `comp`,
// lots, `extrude`, colours and inline calls (see grammar/parser_state.hpp for how bodies are
// compiled and grammars/README.md for the language). A piece's successor is compiled right after
// its Pieces statement, so a body is one flat statement list with forward jumps only.
#include <cmath>
#include <filesystem>
#include <string_view>

#include "base/input_error.hpp"
#include "grammar/parser_state.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "shape/kinds.hpp"

namespace shapevo::grammar_detail {

namespace {
/// The words that begin a statement other than a primitive or an inline call, in the order the
/// error messages list them: these, then the kinds' keywords, then the second list.
constexpr std::string_view kWordsBeforeKinds[] = {"param", "let", "set", "scale", "size", "translate", "rotate", "mirror"};
constexpr std::string_view kWordsAfterKinds[] = {"color", "material", "texture", "extrude", "split", "repeat", "comp", "lot",
                                                 "center", "corners", "edges", "copy", "if", "case", "terminal", "child",
                                                 "send", "gather"};

bool isStatementWord(const std::string& w) {
    for (std::string_view s : kWordsBeforeKinds)
        if (w == s) return true;
    for (std::string_view s : kWordsAfterKinds)
        if (w == s) return true;
    return w == "colour" || w == "else";  // `colour` spells `color`; `else` continues an if
}
}  // namespace

std::string Parser::statementList() const {
    std::string list;
    for (std::string_view s : kWordsBeforeKinds) (list += s) += ", ";
    list += kindKeywords();
    for (std::string_view s : kWordsAfterKinds) (list += ", ") += s;
    return list + " or the name of a rule to run inline";
}

void Parser::compileScalar(const BodyScope& scope, ExprRef& out) {
    const ExpressionContext ctx{&scope.params, scope.attrs, &scope.bindings, true, nullptr};
    ExprRef e[3];
    exprs_.compile(ctx, 1, g_.code, e, g_.maxStack);
    out = e[0];
}

void Parser::compileCondition(const BodyScope& scope, ExprRef& out) {
    const ExpressionContext ctx{&scope.params, scope.attrs, &scope.bindings, true, nullptr};
    ExprRef e[3];
    const SourceLocation at = tokens_.peek().where;
    exprs_.compile(ctx, 3, g_.code, e, g_.maxStack);
    if (exprs_.lastDims() != 1)
        tokens_.fail(at, "a condition must be a scalar (a comparison such as scope.size.x > scope.size.z), "
                         "but this expression is a 3-vector");
    out = e[0];
}

void Parser::compileVector(const BodyScope& scope, ExprRef out[3]) {
    const ExpressionContext ctx{&scope.params, scope.attrs, &scope.bindings, true, nullptr};
    exprs_.compile(ctx, 3, g_.code, out, g_.maxStack);
}

ExprRef Parser::constantExpression(float v) {
    const ExprRef e{std::uint32_t(g_.code.size()), std::uint32_t(g_.code.size() + 1)};
    g_.code.push_back({OpCode::Const, 0, 0, v});
    g_.maxStack = std::max(g_.maxStack, 1);
    ExprRef out = e;
    classifyExpression(g_.code, out);
    return out;
}

std::uint16_t Parser::allocateFrame(Rule& rule, int floats, const SourceLocation& at) {
    if (rule.frameFloats + floats > 256)
        tokens_.fail(at, "rule " + rule.name + " has more than 256 let values and inline arguments");
    const auto index = std::uint16_t(kFrameBase + rule.frameFloats);
    rule.frameFloats = std::uint16_t(rule.frameFloats + floats);
    return index;
}

bool Parser::takeScopeFrameReads() {
    const bool read = exprs_.scopeFrameReads() != framedReads_;
    framedReads_ = exprs_.scopeFrameReads();
    return read;
}

void Parser::frameScopeIfRead(Rule& rule) {
    if (!takeScopeFrameReads()) return;
    Statement frame{};
    frame.kind = StatementKind::ScopeFrame;
    rule.statements.push_back(frame);
}

void Parser::insertScopeFrame(Rule& rule, std::size_t at, std::vector<Piece>& pending) {
    for (std::size_t i = at; i < rule.statements.size(); ++i) {
        Statement& st = rule.statements[i];
        switch (st.kind) {
        case StatementKind::TerminalBegin: case StatementKind::If: case StatementKind::Jump: case StatementKind::Pieces:
            ++st.end;
            break;
        default: break;
        }
        if (st.kind == StatementKind::Pieces && i != at) {  // a nested list, stored already
            const PieceList& list = g_.pieceLists[st.slot];
            for (std::uint32_t k = 0; k < list.count; ++k) {
                ++g_.pieces[list.first + k].begin;
                ++g_.pieces[list.first + k].end;
            }
        }
    }
    for (Piece& p : pending) {
        ++p.begin;
        ++p.end;
    }
    Statement frame{};
    frame.kind = StatementKind::ScopeFrame;
    rule.statements.insert(rule.statements.begin() + std::ptrdiff_t(at), frame);
}

Binding Parser::letValue(Rule& rule, const std::string& name, int dims, const ExprRef* expr, const SourceLocation& at) {
    frameScopeIfRead(rule);
    Statement let{};
    let.kind = StatementKind::Let;
    let.axis = std::uint8_t(dims);
    let.slot = allocateFrame(rule, dims, at);
    for (int c = 0; c < dims; ++c) let.expr[c] = expr[c];
    rule.statements.push_back(let);
    Binding b;
    b.name = name;
    b.dims = dims;
    b.constant = false;
    b.index = let.slot;
    return b;
}

void Parser::parseBlock(Rule& rule, BodyScope& scope, const std::string& closes) {
    const SourceLocation at = tokens_.peek().where;
    while (!tokens_.peek().is('}')) {
        if (tokens_.peek().kind == TokenKind::End)
            tokens_.expected("'}' to close " + closes + (closes.rfind("rule ", 0) == 0 ? "" : " (opened at line " + std::to_string(at.line) + ")"));
        parseStatement(rule, scope);
        if (rule.statements.size() > kMaxStatements) tokens_.fail(at, "rule " + rule.name + " has more than 2^20 statements");
    }
    tokens_.take();
}

/// What a kind's parseArguments reads its arguments with (shape/kinds.hpp). Expressions go
/// into the statement's expr[index] (three of them), a small tag into its slot field.
struct PrimitiveArguments {
    Parser& parser;
    Statement& s;
    const BodyScope& scope;
    /// `WORD EXPR` if the next token is WORD, into expr[index]; otherwise the constant `otherwise`.
    void optionalExpression(std::string_view word, float otherwise, int index = 0) {
        if (parser.tokens_.peek().isWord(word)) {
            parser.tokens_.take();
            expression(index);
        } else {
            constant(index, otherwise);
        }
    }
    /// A scalar expression (required) into expr[index].
    void expression(int index) { parser.compileScalar(scope, s.expr[index]); }
    /// The constant `v` into expr[index].
    void constant(int index, float v) { s.expr[index] = parser.constantExpression(v); }
    /// True (and the word taken) if the next token is the word `w`.
    bool word(std::string_view w) {
        if (!parser.tokens_.peek().isWord(w)) return false;
        parser.tokens_.take();
        return true;
    }
    /// The next token must be `c` (else a located error "expected 'c' WHAT").
    void expect(char c, const std::string& what) { parser.tokens_.expect(c, what); }
    /// A located error at the next token: "expected WHAT, found ...".
    [[noreturn]] void expected(const std::string& what) { parser.tokens_.expected(what); }
    /// True if the next token ends the statement: '}', the end of the file or a word that starts
    /// the next statement (so a kind whose arguments are optional words tells a misspelled one
    /// from the next statement). Takes nothing.
    bool atStatementEnd() const {
        const Token& t = parser.tokens_.peek();
        if (t.is('}') || t.kind == TokenKind::End) return true;
        if (t.kind != TokenKind::Identifier) return false;
        return isStatementWord(t.text) || parser.headerIndex_.count(t.text) > 0 || visitKeyword(t.text, [](auto) {});
    }
    /// A small number the kind's emit reads back as args.slot().
    void tag(std::uint16_t v) { s.slot = v; }
    /// A mesh file name in quotes; its index in Grammar::meshes into slot.
    void meshFile() { s.slot = parser.parseMesh(); }
};

void Parser::parseStatement(Rule& rule, BodyScope& scope) {
    // Blocks, `[ ]`, successors and inline calls nest statements in statements: a limit keeps
    // the parser's recursion off the end of the stack (a located error instead of a crash).
    struct Nesting {
        int& depth;
        ~Nesting() { --depth; }
    } nesting{++statementDepth_};
    if (statementDepth_ > kMaxStatementNesting)
        tokens_.fail(tokens_.peek().where, "statements are nested more than " + std::to_string(kMaxStatementNesting) +
                                               " deep (blocks, [ ], successors and inline calls together)");
    if (tokens_.peek().is('[')) return parseCopy(rule, scope);
    if (tokens_.peek().isWord("gather")) return parseGather(rule, scope);
    const Token word = tokens_.take();
    if (word.kind != TokenKind::Identifier)
        tokens_.fail(word.where, "expected a statement (" + statementList() + "), found " + word.describe());
    if (word.text == "param") return parseParam(rule, scope);
    Statement s{};
    if (word.text == "scale" || word.text == "size" || word.text == "translate") {
        s.kind = word.text == "scale" ? StatementKind::Scale : word.text == "size" ? StatementKind::Size : StatementKind::Translate;
        compileVector(scope, s.expr);
        if (s.kind != StatementKind::Translate) scope.form = ScopeForm::Unknown;
    } else if (word.text == "rotate" || word.text == "mirror") {
        if (terminalAt_ && (word.text == "mirror" || word.text == "set"))
            tokens_.fail(word.where, "'" + word.text + "' cannot be used inside 'terminal { }' (opened at line " +
                                         std::to_string(terminalAt_->line) + ")");
        const SourceLocation at = tokens_.peek().where;
        const std::string axis = tokens_.expectIdentifier("an axis x, y or z after '" + word.text + "'");
        if (axisIndex(axis) < 0) tokens_.fail(at, "expected an axis x, y or z after '" + word.text + "', found '" + axis + "'");
        s.axis = std::uint8_t(axisIndex(axis));
        s.kind = word.text == "rotate" ? StatementKind::Rotate : StatementKind::Mirror;
        if (s.kind == StatementKind::Rotate) compileScalar(scope, s.expr[0]);
    } else if (visitKeyword(word.text, [&](auto kind) {
                   using K = typename decltype(kind)::type;
                   s.kind = StatementKind::Primitive;
                   s.primitive = K::kind;
                   PrimitiveArguments args{*this, s, scope};
                   K::parseArguments(args);
               })) {
    } else if (word.text == "terminal") {
        return parseTerminal(rule, scope, word.where);
    } else if (word.text == "if" || word.text == "case") {
        return parseIf(rule, scope, word.text == "if" ? "if" : "case");
    } else if (word.text == "else") {
        tokens_.fail(word.where, "'else' without an 'if' or 'case' block just before it");
    } else if (word.text == "let") {
        const SourceLocation at = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("a name after 'let'");
        if (isReservedName(name)) tokens_.fail(at, "'" + name + "' is a reserved name and cannot name a let value");
        for (const Param& p : scope.params)
            if (p.name == name) tokens_.fail(at, "'" + name + "' is already a parameter of this rule");
        tokens_.expect('=', "after the name of the let value");
        ExprRef e[3];
        compileVector(scope, e);
        // visible below (a later let of the same name hides it)
        scope.bindings.push_back(letValue(rule, name, exprs_.lastDims(), e, at));
        return;
    } else if (word.text == "set") {
        if (terminalAt_)
            tokens_.fail(word.where, "'set' cannot be used inside 'terminal { }' (opened at line " +
                                         std::to_string(terminalAt_->line) + ")");
        const SourceLocation at = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("the name of a carried attribute after 'set'");
        std::size_t k = 0;
        while (k < g_.carriedNames.size() && g_.carriedNames[k] != name) ++k;
        if (k == g_.carriedNames.size())
            tokens_.fail(at, "'" + name + "' is not a carried attribute: declare it at the top level first (carry " + name +
                                 " = VALUE)");
        tokens_.expect('=', "after 'set " + name + "'");
        s.kind = StatementKind::Set;
        s.slot = std::uint16_t(k);
        compileScalar(scope, s.expr[0]);
    } else if (word.text == "extrude") {
        if (scope.form == ScopeForm::Volume)
            tokens_.fail(word.where, "'extrude' needs a flat scope (a lot, a face from comp, a split of one); "
                                     "this scope is a volume (it was extruded above)");
        s.kind = StatementKind::Extrude;
        compileScalar(scope, s.expr[0]);
        scope.form = ScopeForm::Volume;
    } else if (word.text == "color" || word.text == "colour") {
        s.kind = StatementKind::Color;
        compileVector(scope, s.expr);
        g_.hasAppearance = true;
    } else if (word.text == "material") {
        const Token name = tokens_.take();
        if (name.kind != TokenKind::String && name.kind != TokenKind::Identifier)
            tokens_.fail(name.where, "expected a material name after 'material' (a word or \"text\"), found " + name.describe());
        s.kind = StatementKind::Material;
        std::size_t index = 0;
        while (index < g_.materialNames.size() && g_.materialNames[index] != name.text) ++index;
        if (index == g_.materialNames.size()) {
            if (index >= 65535) tokens_.fail(name.where, "too many materials (at most 65534)");
            g_.materialNames.push_back(name.text);
        }
        s.slot = std::uint16_t(index);
        g_.hasAppearance = true;
    } else if (word.text == "texture") {
        parseTexture(scope, s);
    } else if (word.text == "split" || word.text == "repeat" || word.text == "comp" || word.text == "lot" ||
               word.text == "center" || word.text == "corners" || word.text == "edges" || word.text == "copy") {
        return parsePieces(rule, scope, word);
    } else if (word.text == "child") {
        if (terminalAt_)
            tokens_.fail(word.where, "'child' cannot be used inside 'terminal { }' (opened at line " +
                                         std::to_string(terminalAt_->line) + "): it runs only on genes without children");
        s.kind = StatementKind::Child;
        parseChild(rule, s, word.where, scope);
    } else if (word.text == "send") {
        return parseSend(rule, word);
    } else if (headerIndex_.count(word.text)) {
        // A rule that gathers finishes (its gathers run) before what follows the call: it runs
        // on a copy of the scope, as in `[ Rule ]`.
        if (!bodyGathers(headers_[std::size_t(headerIndex_.at(word.text))].body))
            return inlineCall(rule, scope, word, scope.form);
        const std::size_t at = openCopy(rule, word.where);
        inlineCall(rule, scope, word, scope.form);
        return closeCopy(rule, at);
    } else {
        tokens_.fail(word.where, "unknown statement '" + word.text + "': expected " + statementList());
    }
    frameScopeIfRead(rule);
    rule.statements.push_back(s);
}

void Parser::parseIf(Rule& rule, BodyScope& scope, const char* keyword) {
    // if (C) { A } else if (D) { B } else { E }: If(C)->after A's jump; A; Jump->end; If(D) ...
    std::vector<std::size_t> jumps;
    while (true) {
        const SourceLocation at = tokens_.peek().where;
        tokens_.expect('(', std::string("after '") + keyword + "' (the condition goes in parentheses)");
        Statement cond{};
        cond.kind = StatementKind::If;
        compileCondition(scope, cond.expr[0]);
        tokens_.expect(')', "to close the condition");
        tokens_.expect('{', std::string("to open the block of '") + keyword + "'");
        frameScopeIfRead(rule);
        const std::size_t condIndex = rule.statements.size();
        rule.statements.push_back(cond);
        BodyScope inner = scope;
        parseBlock(rule, inner, std::string("the '") + keyword + "' block opened at line " + std::to_string(at.line));
        const bool isCase = std::string(keyword) == "case";
        const bool more = tokens_.peek().isWord("else") || (isCase && tokens_.peek().isWord("case"));
        if (more) {
            jumps.push_back(rule.statements.size());
            Statement jump{};
            jump.kind = StatementKind::Jump;
            rule.statements.push_back(jump);
        }
        rule.statements[condIndex].end = std::uint32_t(rule.statements.size());
        scope.form = ScopeForm::Unknown;
        if (std::string(keyword) == "case" && tokens_.peek().isWord("case")) {
            tokens_.take();
            continue;
        }
        if (!tokens_.peek().isWord("else")) break;
        tokens_.take();
        if (std::string(keyword) == "if" && tokens_.peek().isWord("if")) {
            tokens_.take();
            continue;
        }
        const SourceLocation elseAt = tokens_.peek().where;
        tokens_.expect('{', "after 'else'");
        BodyScope inner2 = scope;
        parseBlock(rule, inner2, "the 'else' block opened at line " + std::to_string(elseAt.line));
        break;
    }
    for (std::size_t j : jumps) rule.statements[j].end = std::uint32_t(rule.statements.size());
}

void Parser::parseTerminal(Rule& rule, BodyScope& scope, const SourceLocation& at) {
    if (terminalAt_)
        tokens_.fail(at, "'terminal' blocks cannot be nested (the outer one opened at line " +
                             std::to_string(terminalAt_->line) + ")");
    tokens_.expect('{', "after 'terminal'");
    terminalAt_ = at;
    const std::size_t begin = rule.statements.size();
    Statement open{};
    open.kind = StatementKind::TerminalBegin;
    rule.statements.push_back(open);
    BodyScope inner = scope;
    parseBlock(rule, inner, "the terminal block");
    terminalAt_.reset();
    rule.statements[begin].end = std::uint32_t(rule.statements.size());
    Statement close{};
    close.kind = StatementKind::TerminalEnd;
    rule.statements.push_back(close);
}

std::uint16_t Parser::parseMesh() {
    const Token name = tokens_.take();
    if (name.kind != TokenKind::String) tokens_.fail(name.where, "expected a file name in quotes after 'mesh', found " + name.describe());
    for (std::size_t i = 0; i < g_.meshes.size(); ++i)
        if (g_.meshes[i].path == name.text) return std::uint16_t(i);
    if (g_.meshes.size() >= 65535) tokens_.fail(name.where, "too many different meshes (at most 65535)");
    const std::filesystem::path file = std::filesystem::path(g_.path).parent_path() / name.text;
    try {
        g_.meshes.push_back(loadMeshShape(file.string()));
    } catch (const InputError& e) {
        tokens_.fail(name.where, "mesh \"" + name.text + "\": " + e.what());
    }
    g_.meshes.back().path = name.text;
    return std::uint16_t(g_.meshes.size() - 1);
}

}  // namespace shapevo::grammar_detail
