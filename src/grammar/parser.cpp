// Parser: grammar text -> Grammar (see grammar/parser_state.hpp for how a file is read, and
// grammars/README.md for the language). This file: the top level (start, attr, rule headers),
// rule instances, priors and child slots; rule bodies are statements.cpp. Checks after parsing
// live in grammar_checks.cpp.
#include "grammar/parser.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/input_error.hpp"
#include "grammar/grammar_checks.hpp"
#include "grammar/parser_state.hpp"

namespace shapevo {

int Grammar::findRule(const std::string& name) const {
    for (std::size_t i = 0; i < rules.size(); ++i)
        if (rules[i].name == name) return int(i);
    return -1;
}

namespace grammar_detail {

int axisIndex(const std::string& s) { return s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1; }

/// A number as a person would write it in the grammar ("1.5", not "1.500000").
std::string show(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

Parser::Parser(const std::string& text, const std::string& path, const AttrOverrides& overrides)
    : tokens_(text, path), exprs_(tokens_), overrides_(overrides) {
    g_.path = path;
    g_.source = text;
}

Grammar Parser::run() {
    // Pass 1: the top level; rule bodies are skipped (brace by brace) and compiled below.
    std::string startName;
    SourceLocation startAt{};
    while (tokens_.peek().kind != TokenKind::End) {
        const Token& t = tokens_.peek();
        if (t.isWord("start")) {
            if (!startName.empty()) tokens_.fail(t.where, "'start' is given twice");
            tokens_.take();
            startAt = tokens_.peek().where;
            startName = tokens_.expectIdentifier("the name of the start rule after 'start'");
        } else if (t.isWord("attr")) {
            tokens_.take();
            const SourceLocation at = tokens_.peek().where;
            const std::string name = tokens_.expectIdentifier("an attribute name after 'attr'");
            if (attrs_.count(name)) tokens_.fail(at, "attr '" + name + "' is defined twice");
            for (const std::string& c : g_.carriedNames)
                if (c == name) tokens_.fail(at, "'" + name + "' is already a carried attribute");
            if (isReservedName(name))
                tokens_.fail(at, "'" + name + "' is a reserved name (scope, parent, pi and the functions) and cannot name an attr");
            tokens_.expect('=', "after the attribute name");
            double v[3];
            parseConstantValue(v, "the value of attr " + name, nullptr, false);
            const auto o = overrides_.find(name);
            attrs_[name] = o != overrides_.end() ? o->second : v[0];
        } else if (t.isWord("carry")) {
            tokens_.take();
            const SourceLocation at = tokens_.peek().where;
            const std::string name = tokens_.expectIdentifier("the name of a carried attribute after 'carry'");
            if (isReservedName(name))
                tokens_.fail(at, "'" + name + "' is a reserved name (scope, parent, pi and the functions) and cannot name a carried attribute");
            if (attrs_.count(name)) tokens_.fail(at, "'" + name + "' is already an attr");
            for (const std::string& c : g_.carriedNames)
                if (c == name) tokens_.fail(at, "carried attribute '" + name + "' is declared twice");
            if (g_.carriedNames.size() >= kMaxCarried)
                tokens_.fail(at, "too many carried attributes (at most " + std::to_string(kMaxCarried) + ")");
            tokens_.expect('=', "after 'carry " + name + "' (its default value)");
            double v[3];
            parseConstantValue(v, "the default of carried attribute " + name, nullptr, false);
            g_.carriedNames.push_back(name);
            g_.carriedDefaults.push_back(float(v[0]));
        } else if (t.isWord("rule")) {
            tokens_.take();
            RuleHeader h;
            h.where = tokens_.peek().where;
            h.name = tokens_.expectIdentifier("a rule name after 'rule'");
            if (const auto it = headerIndex_.find(h.name); it != headerIndex_.end())
                tokens_.fail(h.where, "rule '" + h.name + "' is defined twice (first at line " +
                                          std::to_string(headers_[it->second].where.line) + ")");
            if (tokens_.peek().is('(')) {
                tokens_.take();
                while (true) {
                    const SourceLocation at = tokens_.peek().where;
                    const std::string a = tokens_.expectIdentifier("an argument name in rule " + h.name + "(...)");
                    if (isReservedName(a)) tokens_.fail(at, "'" + a + "' is a reserved name and cannot name an argument");
                    for (const auto& b : h.args)
                        if (b == a) tokens_.fail(at, "argument '" + a + "' is named twice in rule " + h.name);
                    h.args.push_back(a);
                    h.argWhere.push_back(at);
                    if (tokens_.peek().is(')')) break;
                    tokens_.expect(',', "between the argument names of rule " + h.name);
                }
                tokens_.take();
            }
            tokens_.expect('{', "to open the body of rule " + h.name);
            h.body = tokens_.mark();
            h.attrs = attrs_;
            int depth = 1;
            while (depth > 0) {
                const Token& b = tokens_.peek();
                if (b.kind == TokenKind::End)
                    tokens_.expected("'}' to close rule " + h.name + " (opened at line " + std::to_string(h.where.line) + ")");
                if (b.is('{')) ++depth;
                if (b.is('}')) --depth;
                tokens_.take();
            }
            if (h.args.empty()) {
                if (rules_.size() >= kMaxRules) tokens_.fail(h.where, "too many rules (at most " + std::to_string(kMaxRules) + ")");
                h.plainId = int(rules_.size());
                Rule r;
                r.name = h.name;
                r.where = h.where;
                rules_.push_back(std::move(r));
            }
            headerIndex_.emplace(h.name, int(headers_.size()));
            headers_.push_back(std::move(h));
        } else {
            tokens_.expected("'start', 'attr', 'carry' or 'rule' at the top level");
        }
    }
    const SourceLocation endAt = tokens_.peek().where;
    for (const auto& [name, value] : overrides_) {
        (void)value;
        if (!attrs_.count(name))
            throw InputError(g_.path, "", "grammar.attr." + name + " is set, but the grammar defines no attr '" + name + "'");
    }
    g_.attrs = attrs_;
    exprs_.setCarried(&g_.carriedNames);
    // Pass 2: bodies, plain rules in file order, then instances in order of first use.
    for (std::size_t h = 0; h < headers_.size(); ++h) {
        if (headers_[h].plainId < 0) continue;
        BodyScope scope;
        scope.attrs = &headers_[h].attrs;
        tokens_.seek(headers_[h].body);
        inlineStack_ = {int(h)};
        currentRule_ = std::uint16_t(headers_[h].plainId);
        deferSends_ = true;  // a plain rule may be used only inline, where its sends find their gathers
        parseBody(rules_[std::size_t(headers_[h].plainId)], scope, "rule " + headers_[h].name);
    }
    deferSends_ = false;
    for (std::size_t q = 0; q < queue_.size(); ++q) {
        const PendingInstance p = queue_[q];
        BodyScope scope;
        scope.attrs = &headers_[std::size_t(p.header)].attrs;
        scope.bindings = p.args;
        tokens_.seek(headers_[std::size_t(p.header)].body);
        inlineStack_ = {p.header};
        currentRule_ = std::uint16_t(p.id);
        parseBody(rules_[p.id], scope, "rule " + headers_[std::size_t(p.header)].name);
    }
    g_.rules.assign(std::make_move_iterator(rules_.begin()), std::make_move_iterator(rules_.end()));
    if (headers_.empty()) tokens_.fail(endAt, "the grammar has no rules (expected 'rule NAME { ... }')");
    if (startName.empty()) tokens_.fail({1, 1}, "the grammar has no 'start NAME' line");
    const auto start = headerIndex_.find(startName);
    if (start == headerIndex_.end()) tokens_.fail(startAt, "start rule '" + startName + "' is not defined");
    if (headers_[std::size_t(start->second)].plainId < 0)
        tokens_.fail(startAt, "start rule '" + startName + "' takes arguments; the start rule cannot (write a rule "
                              "without arguments that derives it: child " + startName + "(...))");
    g_.start = std::uint16_t(headers_[std::size_t(start->second)].plainId);
    if (!undefined_.empty()) tokens_.fail(undefined_.front().where, "rule '" + undefined_.front().name + "' is not defined");
    checkDeferredSends();
    g_.usesPiecePlaces = exprs_.piecePlaceReads() > 0;
    g_.marksPieces = g_.usesPieceKeys || g_.usesPiecePlaces;
    checkGrammar(g_, [this](const SourceLocation& at, const std::string& m) { tokens_.fail(at, m); });
    return std::move(g_);
}

int Parser::parseConstantValue(double out[3], const std::string& what, const BodyScope* scope, bool vectorAllowed) {
    const Token& first = tokens_.peek();
    if (first.kind == TokenKind::End || first.is(')') || first.is(']') || first.is(',') || first.is('}'))
        tokens_.expected(what);
    const ExpressionContext ctx{scope ? &scope->params : nullptr, scope ? scope->attrs : &attrs_, scope ? &scope->bindings : nullptr, false,
                                "a constant here"};
    std::vector<Instr> code;
    ExprRef e[3];
    int stack = 0;
    const SourceLocation at = first.where;
    exprs_.compile(ctx, 3, code, e, stack);
    const int dims = exprs_.lastDims();
    if (dims == 3 && !vectorAllowed) tokens_.fail(at, "expected a number for " + what + ", found a vector");
    for (int c = 0; c < 3; ++c) {
        out[c] = double(evaluateConstant(code, e[c]));
        if (!std::isfinite(out[c])) tokens_.fail(at, what + " is not a finite number (" + show(out[c]) + ")");
    }
    return dims;
}

double Parser::parseConstant(const std::string& what, const BodyScope* scope) {
    double v[3];
    parseConstantValue(v, what, scope, false);
    return v[0];
}

void Parser::parseParam(Rule& rule, BodyScope& scope) {
    const SourceLocation at = tokens_.peek().where;
    Param p;
    p.name = tokens_.expectIdentifier("a parameter name after 'param'");
    for (const Param& q : scope.params)
        if (q.name == p.name) tokens_.fail(at, "parameter '" + p.name + "' is declared twice in rule " + rule.name);
    for (const Binding& b : scope.bindings)
        if (b.name == p.name) tokens_.fail(at, "parameter name '" + p.name + "' is already an argument or a let value");
    if (isReservedName(p.name))
        tokens_.fail(at, "parameter name '" + p.name + "' is reserved (scope, parent, pi and the functions)");
    if (scope.attrs->count(p.name)) tokens_.fail(at, "parameter name '" + p.name + "' is already an attr");
    tokens_.expect('=', "after the parameter name");
    const SourceLocation priorAt = tokens_.peek().where;
    const std::string kind =
        tokens_.expectIdentifier("a prior: uniform(a, b), normal(mu, sigma) in [a, b], int(a, b) or choice(x, y, ...)");
    if (kind != "uniform" && kind != "normal" && kind != "int" && kind != "choice")
        tokens_.fail(priorAt, "unknown prior '" + kind + "': expected uniform, normal, int or choice");
    tokens_.expect('(', "after " + kind);
    double a[3], b[3];
    if ((kind == "uniform" || kind == "int" || kind == "normal") && parseRunTimePrior(rule, scope, p, kind, at)) return;
    if (kind == "uniform" || kind == "normal" || kind == "int") {
        int da = parseConstantValue(a, "the first argument of " + kind, &scope, true);
        tokens_.expect(',', "between the two arguments of " + kind);
        int db = parseConstantValue(b, "the second argument of " + kind, &scope, true);
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
            int dl = parseConstantValue(lo, "the lower bound", &scope, true);
            tokens_.expect(',', "between the bounds");
            int dh = parseConstantValue(hi, "the upper bound", &scope, true);
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
            g_.choiceValues.push_back(float(parseConstant("a number in choice(...)", &scope)));
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
    scope.params.push_back(p);
    p.name = scope.prefix + p.name;
    rule.params.push_back(p);
}

std::vector<Binding> Parser::parseArguments(int header, const SourceLocation& at, BodyScope& caller, Rule* rule,
                                            bool requireConstant) {
    const RuleHeader& h = headers_[std::size_t(header)];
    std::vector<Binding> args;
    if (!tokens_.peek().is('(')) {
        if (!h.args.empty())
            tokens_.fail(at, "rule " + h.name + " takes " + std::to_string(h.args.size()) + " argument(s) (" +
                                 [&] {
                                     std::string s;
                                     for (const auto& a : h.args) s += (s.empty() ? "" : ", ") + a;
                                     return s;
                                 }() + "): write " + h.name + "(...)");
        return args;
    }
    if (h.args.empty()) tokens_.fail(tokens_.peek().where, "rule " + h.name + " takes no arguments (define it as rule " + h.name + "(NAME, ...) to give it some)");
    tokens_.take();
    for (std::size_t k = 0; k < h.args.size(); ++k) {
        if (k > 0) {
            if (tokens_.peek().is(')'))
                tokens_.fail(tokens_.peek().where, "rule " + h.name + " takes " + std::to_string(h.args.size()) +
                                                        " arguments, this call gives " + std::to_string(k));
            tokens_.expect(',', "between the arguments of " + h.name);
        }
        Binding b;
        b.name = h.args[k];
        const SourceLocation argAt = tokens_.peek().where;
        const ExpressionContext ctx{&caller.params, caller.attrs, &caller.bindings, true, nullptr};
        ExprRef e[3];
        exprs_.compile(ctx, 3, g_.code, e, g_.maxStack);
        b.dims = exprs_.lastDims();
        b.constant = true;
        for (int c = 0; c < b.dims; ++c) b.constant = b.constant && isConstantExpression(g_.code, e[c]);
        if (b.constant) {
            for (int c = 0; c < 3; ++c) b.value[c] = evaluateConstant(g_.code, e[c]);
        } else if (requireConstant || rule == nullptr) {
            tokens_.fail(argAt, "the arguments of a child must be known when the grammar is read (numbers, attrs, "
                                "the rule's own constant arguments); '" + h.args[k] +
                                    "' here depends on a parameter or the scope: let the child compute it, or "
                                    "use an inline call (a successor of split, comp or a lot)");
        } else {
            b = letValue(*rule, h.args[k], b.dims, e, argAt);
        }
        args.push_back(b);
    }
    if (!tokens_.peek().is(')'))
        tokens_.fail(tokens_.peek().where, "rule " + h.name + " takes " + std::to_string(h.args.size()) +
                                               " argument(s), this call gives more");
    tokens_.take();
    return args;
}

std::uint16_t Parser::instance(int header, const std::vector<Binding>& args) {
    const RuleHeader& h = headers_[std::size_t(header)];
    if (args.empty()) return std::uint16_t(h.plainId);
    std::string name = h.name + "(";
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (k > 0) name += ", ";
        if (args[k].dims == 3)
            name += "(" + show(args[k].value[0]) + ", " + show(args[k].value[1]) + ", " + show(args[k].value[2]) + ")";
        else
            name += show(args[k].value[0]);
    }
    name += ")";
    if (const auto it = instances_.find(name); it != instances_.end()) return it->second;
    if (rules_.size() >= kMaxRules) tokens_.fail(h.where, "too many rules and rule instances (at most " + std::to_string(kMaxRules) + ")");
    const auto id = std::uint16_t(rules_.size());
    Rule r;
    r.name = name;
    r.where = h.where;
    rules_.push_back(std::move(r));
    instances_.emplace(name, id);
    queue_.push_back({header, id, args});
    return id;
}

void Parser::parseChild(Rule& rule, Statement& s, const SourceLocation& childAt, BodyScope& scope) {
    Slot slot;
    do {
        if (!slot.rules.empty()) tokens_.take();
        float weight = 1.0f;
        if (tokens_.peek().is('[')) {
            tokens_.take();
            const SourceLocation at = tokens_.peek().where;
            weight = float(parseConstant("a weight in [ ]", &scope));
            if (!(weight > 0)) tokens_.fail(at, "an alternative's weight must be > 0, got " + show(weight));
            tokens_.expect(']', "after the weight");
        }
        const SourceLocation at = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("a rule name after 'child'");
        if ((name == "prob" || name == "max") && tokens_.peek().kind == TokenKind::Number)
            tokens_.fail(at, "expected a rule name after 'child', found '" + name + "' (" + name +
                                 " comes after the rule names: child A " + name + " N)");
        const auto h = headerIndex_.find(name);
        std::uint16_t id = 0;
        if (h == headerIndex_.end()) {
            undefined_.push_back({name, at});
            if (tokens_.peek().is('(')) {  // skip the arguments of an undefined rule
                int depth = 0;
                do {
                    if (tokens_.peek().is('(')) ++depth;
                    if (tokens_.peek().is(')')) --depth;
                    if (tokens_.peek().kind == TokenKind::End) tokens_.expected("')' to close the arguments");
                    tokens_.take();
                } while (depth > 0);
            }
        } else {
            id = instance(h->second, parseArguments(h->second, at, scope, nullptr, true));
        }
        slot.rules.push_back(id);
        slot.weights.push_back(weight);
        if (tokens_.peek().is(',') && tokens_.peekSecond().is('['))
            tokens_.fail(tokens_.peek().where, "alternatives of a child slot are separated by '|', not ',' "
                                               "(child [0.25] B | [0.75] C)");
    } while (tokens_.peek().is('|'));
    float totalWeight = 0;
    for (float w : slot.weights) totalWeight += w;
    if (!std::isfinite(totalWeight))
        tokens_.fail(childAt, "the weights of this child slot add up to more than a 32-bit float can hold");
    bool seenProb = false, seenMax = false, seenOptional = false;
    while (tokens_.peek().isWord("prob") || tokens_.peek().isWord("max") || tokens_.peek().isWord("optional")) {
        const Token key = tokens_.take();
        if (key.text == "optional") {
            if (seenOptional) tokens_.fail(key.where, "'optional' is given twice for this child slot");
            seenOptional = slot.optional = true;
            continue;
        }
        bool& seen = key.text == "prob" ? seenProb : seenMax;
        if (seen) tokens_.fail(key.where, "'" + key.text + "' is given twice for this child slot");
        seen = true;
        const SourceLocation at = tokens_.peek().where;
        const double v = parseConstant("a number after '" + key.text + "'", &scope);
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

}  // namespace grammar_detail

Grammar parseShapeGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return grammar_detail::Parser(text, path, overrides).run();
}

}  // namespace shapevo
