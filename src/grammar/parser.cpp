// Parser: grammar text -> Grammar. Syntax (see grammars/README.md):
//   start NAME
//   attr NAME = NUMBER
//   rule NAME { param NAME = PRIOR ...  STATEMENT ... }
// with STATEMENT one of scale/size/translate VEC, rotate AXIS EXPR, mirror AXIS, a primitive
// (its keyword and arguments are its kind's, shape/kinds/: box, cylinder, cone [top EXPR], sphere,
// mesh "FILE", roof [top (EXPR, EXPR) | gable | hip | pyramid], paraboloid), terminal
// { STATEMENTS }, child [w] A | [w] B ... [prob P] [max K]. Checks after parsing live in
// grammar_checks.cpp.
#include "grammar/parser.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "grammar/expression.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "grammar/grammar_checks.hpp"
#include "base/input_error.hpp"
#include "shape/kinds.hpp"

namespace shapevo {

int Grammar::findRule(const std::string& name) const {
    for (std::size_t i = 0; i < rules.size(); ++i)
        if (rules[i].name == name) return int(i);
    return -1;
}

namespace {

int axisIndex(const std::string& s) { return s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1; }

/// A number as a person would write it in the grammar ("1.5", not "1.500000").
std::string show(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

/// Rule ids are 16-bit in genes; the largest |bound| of int(a, b) keeps every whole number in
/// range exactly representable as a float.
constexpr std::size_t kMaxRules = 65535;
constexpr double kMaxIntBound = 16777216.0;  // 2^24
constexpr int kMaxChildPositions = 64;

class Parser {
public:
    Parser(const std::string& text, const std::string& path) : tokens_(text, path), exprs_(tokens_) {
        g_.path = path;
        g_.source = text;
    }

    Grammar run() {
        SourceLocation startAt{};
        while (tokens_.peek().kind != TokenKind::End) {
            const Token& t = tokens_.peek();
            if (t.isWord("start")) {
                if (!startName_.empty()) tokens_.fail(t.where, "'start' is given twice");
                tokens_.take();
                startAt = tokens_.peek().where;
                startName_ = tokens_.expectIdentifier("the name of the start rule after 'start'");
            } else if (t.isWord("attr")) {
                parseAttr();
            } else if (t.isWord("rule")) {
                parseRule();
            } else {
                tokens_.expected("'start', 'attr' or 'rule' at the top level");
            }
        }
        if (g_.rules.empty()) tokens_.fail(tokens_.peek().where, "the grammar has no rules (expected 'rule NAME { ... }')");
        if (startName_.empty()) tokens_.fail({1, 1}, "the grammar has no 'start NAME' line");
        const auto start = ruleIndex_.find(startName_);
        if (start == ruleIndex_.end()) tokens_.fail(startAt, "start rule '" + startName_ + "' is not defined");
        g_.start = std::uint16_t(start->second);
        for (const auto& ref : pendingRefs_) {
            const auto r = ruleIndex_.find(ref.name);
            if (r == ruleIndex_.end()) tokens_.fail(ref.where, "rule '" + ref.name + "' is not defined");
            g_.rules[ref.rule].slots[ref.slot].rules[ref.alternative] = std::uint16_t(r->second);
        }
        checkGrammar(g_, [this](const SourceLocation& at, const std::string& m) { tokens_.fail(at, m); });
        return std::move(g_);
    }

private:
    struct RuleRef {
        std::string name;
        SourceLocation where;
        std::size_t rule, slot, alternative;
    };

    double parseConstant(const std::string& what) {
        const Token& t = tokens_.peek();
        double sign = 1;
        if (t.is('-')) {
            tokens_.take();
            sign = -1;
        }
        const Token& v = tokens_.peek();
        if (v.kind == TokenKind::Number) return sign * tokens_.take().number;
        if (v.kind == TokenKind::Identifier) {
            if (auto it = attrs_.find(v.text); it != attrs_.end()) {
                tokens_.take();
                return sign * it->second;
            }
            if (v.text == "pi") {
                tokens_.take();
                return sign * M_PI;
            }
        }
        tokens_.expected(what);
    }

    /// A constant or a vector constant (a, b, c); returns the number of components.
    int parseConstantVector(double out[3], const std::string& what) {
        if (tokens_.peek().is('(')) {
            tokens_.take();
            for (int c = 0; c < 3; ++c) {
                if (c > 0) tokens_.expect(',', "between vector components");
                out[c] = parseConstant("a number for component " + std::to_string(c + 1) + " of " + what);
            }
            tokens_.expect(')', "to close the vector");
            return 3;
        }
        out[0] = out[1] = out[2] = parseConstant(what);
        return 1;
    }

    void parseAttr() {
        tokens_.take();
        const SourceLocation at = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("an attribute name after 'attr'");
        if (attrs_.count(name)) tokens_.fail(at, "attr '" + name + "' is defined twice");
        if (isReservedName(name))
            tokens_.fail(at, "'" + name + "' is a reserved name (scope, parent, pi and the functions) and cannot name an attr");
        tokens_.expect('=', "after the attribute name");
        attrs_[name] = parseConstant("a number as the value of attr " + name);
    }

    void parseRule() {
        tokens_.take();
        Rule r;
        r.where = tokens_.peek().where;
        r.name = tokens_.expectIdentifier("a rule name after 'rule'");
        if (const auto it = ruleIndex_.find(r.name); it != ruleIndex_.end())
            tokens_.fail(r.where, "rule '" + r.name + "' is defined twice (first at line " +
                                      std::to_string(g_.rules[it->second].where.line) + ")");
        if (g_.rules.size() >= kMaxRules)
            tokens_.fail(r.where, "too many rules (at most " + std::to_string(kMaxRules) + ")");
        ruleIndex_.emplace(r.name, int(g_.rules.size()));
        tokens_.expect('{', "to open the body of rule " + r.name);
        g_.rules.push_back(std::move(r));
        Rule& rule = g_.rules.back();
        while (!tokens_.peek().is('}')) {
            if (tokens_.peek().kind == TokenKind::End)
                tokens_.expected("'}' to close rule " + rule.name + " (opened at line " + std::to_string(rule.where.line) + ")");
            parseStatement(rule);
        }
        tokens_.take();
    }

    void parseParam(Rule& rule) {
        const SourceLocation at = tokens_.peek().where;
        Param p;
        p.name = tokens_.expectIdentifier("a parameter name after 'param'");
        for (const Param& q : rule.params)
            if (q.name == p.name) tokens_.fail(at, "parameter '" + p.name + "' is declared twice in rule " + rule.name);
        if (isReservedName(p.name))
            tokens_.fail(at, "parameter name '" + p.name + "' is reserved (scope, parent, pi and the functions)");
        if (attrs_.count(p.name)) tokens_.fail(at, "parameter name '" + p.name + "' is already an attr");
        tokens_.expect('=', "after the parameter name");
        const SourceLocation priorAt = tokens_.peek().where;
        const std::string kind =
            tokens_.expectIdentifier("a prior: uniform(a, b), normal(mu, sigma) in [a, b], int(a, b) or choice(x, y, ...)");
        if (kind != "uniform" && kind != "normal" && kind != "int" && kind != "choice")
            tokens_.fail(priorAt, "unknown prior '" + kind + "': expected uniform, normal, int or choice");
        tokens_.expect('(', "after " + kind);
        double a[3], b[3];
        if (kind == "uniform" || kind == "normal" || kind == "int") {
            int da = parseConstantVector(a, "the first argument of " + kind);
            tokens_.expect(',', "between the two arguments of " + kind);
            int db = parseConstantVector(b, "the second argument of " + kind);
            tokens_.expect(')', "after the two arguments of " + kind);
            p.dims = std::uint8_t(std::max(da, db));
            if (kind == "int" && p.dims != 1) tokens_.fail(priorAt, "int(a, b) takes two numbers, not vectors");
            for (int c = 0; c < 3; ++c) {
                Prior& pr = p.prior[c];
                pr.kind = kind == "uniform" ? PriorKind::Uniform : kind == "normal" ? PriorKind::Normal : PriorKind::Int;
                if (kind == "normal") {
                    pr.mu = float(a[c]);
                    pr.sigma = float(b[c]);
                    if (!(b[c] > 0)) tokens_.fail(priorAt, "normal(mu, sigma) needs sigma > 0, got " + show(b[c]));
                } else {
                    pr.lo = float(a[c]);
                    pr.hi = float(b[c]);
                    if (!(a[c] <= b[c]))
                        tokens_.fail(priorAt, kind + "(a, b) needs a <= b, got " + show(a[c]) + " > " + show(b[c]));
                }
            }
            if (kind == "int") {
                if (std::fabs(a[0]) > kMaxIntBound || std::fabs(b[0]) > kMaxIntBound)
                    tokens_.fail(priorAt, "int(a, b) bounds must lie within [-16777216, 16777216]");
                if (std::ceil(a[0]) > std::floor(b[0]))
                    tokens_.fail(priorAt, "int(" + show(a[0]) + ", " + show(b[0]) + ") contains no whole number");
            }
            if (kind == "normal") {
                if (!tokens_.peek().isWord("in")) tokens_.expected("'in [lo, hi]' after normal(mu, sigma): its support must be bounded");
                tokens_.take();
                tokens_.expect('[', "after 'in'");
                double lo[3], hi[3];
                int dl = parseConstantVector(lo, "the lower bound");
                tokens_.expect(',', "between the bounds");
                int dh = parseConstantVector(hi, "the upper bound");
                tokens_.expect(']', "to close the bounds");
                p.dims = std::uint8_t(std::max<int>({p.dims, dl, dh}));
                for (int c = 0; c < 3; ++c) {
                    p.prior[c].lo = float(lo[c]);
                    p.prior[c].hi = float(hi[c]);
                    if (!(lo[c] <= hi[c]))
                        tokens_.fail(priorAt, "normal(...) in [lo, hi] needs lo <= hi, got " + show(lo[c]) + " > " + show(hi[c]));
                }
            }
        } else {  // choice
            Prior& pr = p.prior[0];
            pr.kind = PriorKind::Choice;
            pr.choiceBegin = std::uint32_t(g_.choiceValues.size());
            do {
                if (pr.choiceCount > 0) tokens_.take();
                g_.choiceValues.push_back(float(parseConstant("a number in choice(...)")));
                ++pr.choiceCount;
            } while (tokens_.peek().is(','));
            tokens_.expect(')', "to close choice(...)");
            pr.lo = pr.hi = g_.choiceValues[pr.choiceBegin];
            for (std::uint32_t i = 0; i < pr.choiceCount; ++i) {
                pr.lo = std::min(pr.lo, g_.choiceValues[pr.choiceBegin + i]);
                pr.hi = std::max(pr.hi, g_.choiceValues[pr.choiceBegin + i]);
            }
        }
        p.first = rule.paramFloats;
        rule.paramFloats = std::uint16_t(rule.paramFloats + p.dims);
        if (rule.paramFloats > 256) tokens_.fail(at, "rule " + rule.name + " has more than 256 parameter values");
        rule.params.push_back(p);
    }

    void parseChild(Rule& rule, Statement& s, const SourceLocation& childAt) {
        Slot slot;
        do {
            if (!slot.rules.empty()) tokens_.take();
            float weight = 1.0f;
            if (tokens_.peek().is('[')) {
                tokens_.take();
                const SourceLocation at = tokens_.peek().where;
                weight = float(parseConstant("a weight in [ ]"));
                if (!(weight > 0)) tokens_.fail(at, "an alternative's weight must be > 0, got " + show(weight));
                tokens_.expect(']', "after the weight");
            }
            const SourceLocation at = tokens_.peek().where;
            const std::string name = tokens_.expectIdentifier("a rule name after 'child'");
            if ((name == "prob" || name == "max") && tokens_.peek().kind == TokenKind::Number)
                tokens_.fail(at, "expected a rule name after 'child', found '" + name + "' (" + name +
                                     " comes after the rule names: child A " + name + " N)");
            pendingRefs_.push_back({name, at, std::size_t(&rule - g_.rules.data()), rule.slots.size(), slot.rules.size()});
            slot.rules.push_back(0);
            slot.weights.push_back(weight);
        } while (tokens_.peek().is('|'));
        float totalWeight = 0;
        for (float w : slot.weights) totalWeight += w;
        if (!std::isfinite(totalWeight))
            tokens_.fail(childAt, "the weights of this child slot add up to more than a 32-bit float can hold");
        bool seenProb = false, seenMax = false;
        while (tokens_.peek().isWord("prob") || tokens_.peek().isWord("max")) {
            const Token key = tokens_.take();
            bool& seen = key.text == "prob" ? seenProb : seenMax;
            if (seen) tokens_.fail(key.where, "'" + key.text + "' is given twice for this child slot");
            seen = true;
            const SourceLocation at = tokens_.peek().where;
            const double v = parseConstant("a number after '" + key.text + "'");
            if (key.text == "prob") {
                if (!(v >= 0 && v <= 1)) tokens_.fail(at, "prob must be in [0, 1], got " + show(v));
                slot.probability = float(v);
            } else {
                if (!(v >= 1 && v <= kMaxChildPositions && v == std::floor(v)))
                    tokens_.fail(at, "max must be a whole number from 1 to 64, got " + show(v));
                slot.maxCount = std::uint16_t(v);
            }
        }
        if (rule.childOffsets + slot.maxCount > kMaxChildPositions)
            tokens_.fail(childAt, "rule " + rule.name + " has more than 64 child positions (the sum of its slots' max)");
        slot.firstChild = rule.childOffsets;
        slot.edge = g_.edgeCount++;
        rule.childOffsets = std::uint16_t(rule.childOffsets + slot.maxCount);
        s.slot = std::uint16_t(rule.slots.size());
        rule.slots.push_back(std::move(slot));
    }

    void parseStatement(Rule& rule) {
        const Token word = tokens_.take();
        if (word.kind != TokenKind::Identifier)
            tokens_.fail(word.where, "expected a statement (" + statementList() + "), found " + word.describe());
        if (word.text == "param") return parseParam(rule);
        Statement s{};
        const ExpressionContext ctx{&rule.params, &attrs_};
        if (word.text == "scale" || word.text == "size" || word.text == "translate") {
            s.kind = word.text == "scale" ? StatementKind::Scale : word.text == "size" ? StatementKind::Size : StatementKind::Translate;
            exprs_.compile(ctx, 3, g_.code, s.expr, g_.maxStack);
        } else if (word.text == "rotate" || word.text == "mirror") {
            if (terminalAt_ && word.text == "mirror")
                tokens_.fail(word.where, "'mirror' cannot be used inside 'terminal { }' (opened at line " +
                                             std::to_string(terminalAt_->line) + ")");
            const SourceLocation at = tokens_.peek().where;
            const std::string axis = tokens_.expectIdentifier("an axis x, y or z after '" + word.text + "'");
            if (axisIndex(axis) < 0) tokens_.fail(at, "expected an axis x, y or z after '" + word.text + "', found '" + axis + "'");
            s.axis = std::uint8_t(axisIndex(axis));
            s.kind = word.text == "rotate" ? StatementKind::Rotate : StatementKind::Mirror;
            if (s.kind == StatementKind::Rotate) exprs_.compile(ctx, 1, g_.code, s.expr, g_.maxStack);
        } else if (visitKeyword(word.text, [&](auto kind) {
                       using K = typename decltype(kind)::type;
                       s.kind = StatementKind::Primitive;
                       s.primitive = K::kind;
                       PrimitiveArguments args{*this, s, ctx};
                       K::parseArguments(args);
                   })) {
        } else if (word.text == "terminal") {
            return parseTerminal(rule, word.where);
        } else if (word.text == "child") {
            if (terminalAt_)
                tokens_.fail(word.where, "'child' cannot be used inside 'terminal { }' (opened at line " +
                                             std::to_string(terminalAt_->line) + "): it runs only on genes without children");
            s.kind = StatementKind::Child;
            parseChild(rule, s, word.where);
        } else {
            tokens_.fail(word.where, "unknown statement '" + word.text + "': expected " + statementList());
        }
        rule.statements.push_back(s);
    }

    static std::string statementList() {
        return "param, scale, size, translate, rotate, mirror, " + kindKeywords() + ", terminal or child";
    }

    /// What a kind's parseArguments reads its arguments with (shape/kinds.hpp). Expressions go
    /// into the statement's expr[index] (three of them), a small tag into its slot field.
    struct PrimitiveArguments {
        Parser& parser;
        Statement& s;
        const ExpressionContext& ctx;
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
        void expression(int index) {
            ExprRef e[3];
            parser.exprs_.compile(ctx, 1, parser.g_.code, e, parser.g_.maxStack);
            s.expr[index] = e[0];
        }
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
        /// True if the next token ends the statement: '}', the end of the file or a word that
        /// starts the next statement (a kind whose arguments are optional words tells a
        /// misspelled one from the next statement with it). Takes nothing.
        bool atStatementEnd() const {
            const Token& t = parser.tokens_.peek();
            if (t.is('}') || t.kind == TokenKind::End) return true;
            if (t.kind != TokenKind::Identifier) return false;
            for (const char* w : {"param", "scale", "size", "translate", "rotate", "mirror", "terminal", "child"})
                if (t.text == w) return true;
            return visitKeyword(t.text, [](auto) {});
        }
        /// A small number the kind's emit reads back as args.slot().
        void tag(std::uint16_t v) { s.slot = v; }
        /// A mesh file name in quotes; its index in Grammar::meshes into slot.
        void meshFile() { s.slot = parser.parseMesh(); }
    };

    ExprRef constantExpression(float v) {
        const ExprRef e{std::uint32_t(g_.code.size()), std::uint32_t(g_.code.size() + 1)};
        g_.code.push_back({OpCode::Const, 0, 0, v});
        g_.maxStack = std::max(g_.maxStack, 1);
        return e;
    }

    /// terminal { STATEMENTS }: statements that run only when the gene has no expressed
    /// children (a branch that ends gets its foliage); the scope is restored after the block.
    void parseTerminal(Rule& rule, const SourceLocation& at) {
        if (terminalAt_)
            tokens_.fail(at, "'terminal' blocks cannot be nested (the outer one opened at line " +
                                 std::to_string(terminalAt_->line) + ")");
        tokens_.expect('{', "after 'terminal'");
        terminalAt_ = at;
        const std::size_t begin = rule.statements.size();
        Statement open{};
        open.kind = StatementKind::TerminalBegin;
        rule.statements.push_back(open);
        while (!tokens_.peek().is('}')) {
            if (tokens_.peek().kind == TokenKind::End)
                tokens_.expected("'}' to close the terminal block opened at line " + std::to_string(at.line));
            parseStatement(rule);
        }
        tokens_.take();
        terminalAt_.reset();
        rule.statements[begin].end = std::uint32_t(rule.statements.size());
        Statement close{};
        close.kind = StatementKind::TerminalEnd;
        rule.statements.push_back(close);
    }

    /// mesh "file": a closed OBJ/PLY/STL mesh, found relative to the grammar file's folder and
    /// read once (the same file twice shares one shape).
    std::uint16_t parseMesh() {
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

    TokenStream tokens_;
    ExpressionCompiler exprs_;
    Grammar g_;
    std::map<std::string, double> attrs_;
    std::string startName_;
    std::vector<RuleRef> pendingRefs_;
    std::map<std::string, int> ruleIndex_;
    std::optional<SourceLocation> terminalAt_;  ///< inside `terminal { }`: where it opened
};

}  // namespace

Grammar parseGrammar(const std::string& text, const std::string& path) { return Parser(text, path).run(); }

Grammar loadGrammar(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a grammar file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open grammar file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path, "", "cannot read grammar file");
    return parseGrammar(ss.str(), path);
}

}  // namespace shapevo
