// Statements that make several scopes out of one, each running a successor: split and repeat
// along an axis, comp (a volume's faces), lots (rect, circle, center, corners, edges), copy (N
// times the scope itself). The
// Pieces statement comes first (after a ScopeFrame when its own numbers read scope.origin or
// scope.axis); each successor's statements follow it in the rule, in order
// (a successor named twice without arguments, or comp's `side`, is compiled once and shared),
// then the statement after the whole construct. Successors: a rule name with arguments (compiled inline: its
// parameters and child slots become this gene's), `{ statements }`, or `nil`.
#include <cmath>

#include "grammar/parser_state.hpp"

namespace shapevo::grammar_detail {

namespace {
constexpr const char* kFaceNames[kFaces] = {"top", "bottom", "front", "back", "left", "right"};
}

void Parser::parseSuccessor(Rule& rule, BodyScope& scope, Piece& piece, ScopeForm form, CompiledSuccessors* compiled) {
    piece.begin = std::uint32_t(rule.statements.size());
    const Token& t = tokens_.peek();
    if (compiled && t.kind == TokenKind::Identifier && !tokens_.peekSecond().is('(')) {
        if (auto it = compiled->find(t.text); it != compiled->end()) {
            tokens_.take();
            piece.begin = it->second.first;
            piece.end = it->second.second;
            return;
        }
    }
    if (t.isWord("nil")) {
        tokens_.take();
    } else if (t.is('{')) {
        const SourceLocation at = tokens_.take().where;
        BodyScope inner = scope;
        inner.form = form;
        parseBlock(rule, inner, "the successor block opened at line " + std::to_string(at.line));
    } else if (t.kind == TokenKind::Identifier) {
        const Token name = tokens_.take();
        if (!headerIndex_.count(name.text))
            tokens_.fail(name.where, "rule '" + name.text + "' is not defined (a successor is a rule name, "
                                     "'{ statements }' or nil)");
        const bool plain = !tokens_.peek().is('(');
        inlineCall(rule, scope, name, form);
        if (compiled && plain) (*compiled)[name.text] = {piece.begin, std::uint32_t(rule.statements.size())};
    } else {
        tokens_.expected("a successor: a rule name, '{ statements }' or nil");
    }
    piece.end = std::uint32_t(rule.statements.size());
}

void Parser::inlineCall(Rule& rule, BodyScope& caller, const Token& name, ScopeForm form) {
    const int header = headerIndex_.at(name.text);
    for (std::size_t k = 0; k < inlineStack_.size(); ++k) {
        if (inlineStack_[k] != header) continue;
        std::string path;
        for (std::size_t j = k; j < inlineStack_.size(); ++j) path += headers_[std::size_t(inlineStack_[j])].name + " -> ";
        tokens_.fail(name.where, "inline calls never end: " + path + name.text +
                                     "; a rule cannot run inside itself (recursion goes through 'child')");
    }
    if (int(inlineStack_.size()) >= kMaxInlineDepth)
        tokens_.fail(name.where, "inline calls are nested more than " + std::to_string(kMaxInlineDepth) + " deep");
    recordInlineCall(name);
    BodyScope callee;
    callee.attrs = &headers_[std::size_t(header)].attrs;
    callee.prefix = caller.prefix + name.text + ".";
    callee.form = form;
    callee.bindings = parseArguments(header, name.where, caller, &rule, false);
    inlineStack_.push_back(header);
    const std::size_t resume = tokens_.mark();
    tokens_.seek(headers_[std::size_t(header)].body);
    parseBody(rule, callee, "rule " + name.text);
    tokens_.seek(resume);
    inlineStack_.pop_back();
}

void Parser::recordInlineCall(const Token& name) {
    // A rule's calls are recorded while its body compiles, so they are the last entries.
    for (auto c = g_.inlineCalls.rbegin(); c != g_.inlineCalls.rend() && c->rule == currentRule_; ++c)
        if (c->callee == name.text) return;
    g_.inlineCalls.push_back({currentRule_, name.text, name.where});
}

void Parser::parseSuccessorList(Rule& rule, BodyScope& scope, std::vector<Piece>& pieces, ScopeForm form) {
    CompiledSuccessors compiled;
    do {
        if (!pieces.empty()) tokens_.take();
        Piece p;
        parseSuccessor(rule, scope, p, form, &compiled);
        pieces.push_back(p);
    } while (tokens_.peek().is('|'));
}

void Parser::parseSplitList(Rule& rule, BodyScope& scope, std::vector<Piece>& pieces, bool& readsScope) {
    const SourceLocation open = tokens_.peek().where;
    tokens_.expect('{', "after the split axis (split AXIS { SIZE: SUCCESSOR | ... })");
    CompiledSuccessors compiled;
    bool inGroup = false, hadGroup = false;
    while (true) {
        if (tokens_.peek().is('{')) {
            if (inGroup || hadGroup)
                tokens_.fail(tokens_.peek().where, "a split has at most one repeat group { ... }*, and groups do not nest");
            tokens_.take();
            inGroup = true;
        }
        Piece p;
        p.repeated = inGroup;
        const Token& t = tokens_.peek();
        if (t.is('\'')) {
            tokens_.take();
            p.size = PieceSize::Relative;
        } else if (t.is('~')) {
            tokens_.take();
            p.size = PieceSize::Floating;
        }
        if (tokens_.peek().is(':') || tokens_.peek().is('|') || tokens_.peek().is('}'))
            tokens_.expected("the size of a piece (a number of units, 'FRACTION or ~SIZE) before ':'");
        compileScalar(scope, p.value);
        readsScope = takeScopeFrameReads() || readsScope;
        tokens_.expect(':', "after the size of a piece (SIZE: SUCCESSOR)");
        parseSuccessor(rule, scope, p, scope.form, &compiled);
        pieces.push_back(p);
        if (pieces.size() > kMaxSplitPieces)
            tokens_.fail(open, "a split lists at most " + std::to_string(kMaxSplitPieces) + " pieces (use a repeat group for more)");
        if (inGroup && tokens_.peek().is('}')) {
            tokens_.take();
            tokens_.expect('*', "after the '}' of a repeat group ({ SIZE: A | ... }* repeats as many times as fit)");
            inGroup = false;
            hadGroup = true;
        }
        if (tokens_.peek().is('|')) {
            tokens_.take();
            continue;
        }
        if (tokens_.peek().is('}') && !inGroup) {
            tokens_.take();
            break;
        }
        tokens_.expected(inGroup ? "'|' or '}*' in the repeat group opened inside the split at line " + std::to_string(open.line)
                                 : "'|' between the pieces of a split, or '}' to close it");
    }
    if (tokens_.peek().is('*')) {
        if (hadGroup) tokens_.fail(tokens_.peek().where, "a split with a repeat group cannot also repeat as a whole");
        tokens_.take();
        for (Piece& p : pieces) p.repeated = true;
    }
}

void Parser::parseNumberTuple(const BodyScope& scope, PieceList& list, int first, int n, const std::string& what,
                              bool& readsScope) {
    tokens_.expect('(', "to open " + what);
    for (int k = 0; k < n; ++k) {
        if (k > 0) {
            if (tokens_.peek().is(')'))
                tokens_.fail(tokens_.peek().where, what + " has " + std::to_string(n) + " numbers, this gives " + std::to_string(k));
            tokens_.expect(',', "between the numbers of " + what);
        }
        compileScalar(scope, list.arg[first + k]);
        readsScope = takeScopeFrameReads() || readsScope;
    }
    if (!tokens_.peek().is(')'))
        tokens_.fail(tokens_.peek().where, what + " has " + std::to_string(n) + " numbers, this gives more");
    tokens_.take();
}

void Parser::parseCompFaces(Rule& rule, BodyScope& scope, const Token& word, std::vector<Piece>& pieces) {
    if (scope.form == ScopeForm::Flat)
        tokens_.fail(word.where, "'comp' takes a volume apart into its faces, but this scope is flat (a lot or a "
                                 "face): extrude it first");
    tokens_.expect('{', "after 'comp' (comp { FACE: SUCCESSOR | ... })");
    CompiledSuccessors compiled;
    bool named[kFaces] = {};
    std::optional<Piece> side;
    while (true) {
        const SourceLocation fa = tokens_.peek().where;
        const std::string face = tokens_.expectIdentifier("a face name (top, bottom, front, back, left, right or side)");
        int f = -1;
        for (int k = 0; k < kFaces; ++k)
            if (face == kFaceNames[k]) f = k;
        if (f < 0 && face != "side")
            tokens_.fail(fa, "unknown face '" + face + "': expected top, bottom, front, back, left, right or side");
        if ((f >= 0 && named[f]) || (face == "side" && side))
            tokens_.fail(fa, "face '" + face + "' is given twice in this comp");
        tokens_.expect(':', "after the face name (FACE: SUCCESSOR)");
        Piece p;
        parseSuccessor(rule, scope, p, ScopeForm::Flat, &compiled);
        if (f >= 0) {
            named[f] = true;
            p.face = std::uint8_t(f);
            pieces.push_back(p);
        } else {
            side = p;
        }
        if (tokens_.peek().is('|')) {
            tokens_.take();
            continue;
        }
        tokens_.expect('}', "to close the comp (or '|' before the next face)");
        break;
    }
    if (side) {
        for (FaceName f : {FaceName::Front, FaceName::Right, FaceName::Back, FaceName::Left}) {
            if (named[int(f)]) continue;
            Piece p = *side;
            p.face = std::uint8_t(f);
            pieces.push_back(p);
        }
    }
}

void Parser::parseLotPieces(Rule& rule, BodyScope& scope, const Token& word, PieceList& list, std::vector<Piece>& pieces,
                            bool& readsScope) {
    const std::string& w = word.text;
    if (w != "lot" && scope.form == ScopeForm::Volume)
        tokens_.fail(word.where, "'" + w + "' needs a flat scope (a lot or a face); this scope is a "
                                 "volume (extruded above): take a face with comp first");
    if (w == "lot") {
        const SourceLocation ka = tokens_.peek().where;
        const std::string kind = tokens_.expectIdentifier("'rect' or 'circle' after 'lot'");
        if (kind == "rect") {
            list.kind = PiecesKind::LotRect;
            parseNumberTuple(scope, list, 0, 4, "lot rect (x1, y1, x2, y2)", readsScope);
        } else if (kind == "circle") {
            list.kind = PiecesKind::LotCircle;
            parseNumberTuple(scope, list, 0, 3, "lot circle (cx, cy, r)", readsScope);
        } else {
            tokens_.fail(ka, "unknown lot '" + kind + "': expected rect (x1, y1, x2, y2) or circle (cx, cy, r)");
        }
        parseSuccessorList(rule, scope, pieces, ScopeForm::Flat);
        if (pieces.size() > 1) tokens_.fail(ka, "a lot has one successor");
    } else if (w == "center") {
        list.kind = PiecesKind::Center;
        parseNumberTuple(scope, list, 0, 2, "center (width, depth)", readsScope);
        parseSuccessorList(rule, scope, pieces, ScopeForm::Flat);
    } else if (w == "corners") {
        list.kind = PiecesKind::Corners;
        parseNumberTuple(scope, list, 0, 2, "corners (rx, ry)", readsScope);
        if (tokens_.peek().isWord("on")) {
            tokens_.take();
            parseNumberTuple(scope, list, 2, 4, "corners ... on (c1, c2, c3, c4)", readsScope);
        } else {
            for (int k = 2; k < 6; ++k) list.arg[k] = constantExpression(1.0f);
        }
        if (tokens_.peek().isWord("inside")) {
            tokens_.take();
            list.floating = true;  // the lots lie inside, one corner on the parent's
        }
        parseSuccessorList(rule, scope, pieces, ScopeForm::Flat);
    } else {  // edges
        list.kind = PiecesKind::Edges;
        parseNumberTuple(scope, list, 0, 2, "edges (rx, ry)", readsScope);
        parseNumberTuple(scope, list, 2, 4, "edges ... (n1, n2, n3, n4)", readsScope);
        parseSuccessorList(rule, scope, pieces, ScopeForm::Flat);
    }
}

void Parser::parsePieces(Rule& rule, BodyScope& scope, const Token& word) {
    PieceList list;
    std::vector<Piece> pieces;
    bool readsScope = false;  // its own expressions (not its successors') read scope.origin / scope.axis
    const std::size_t at = rule.statements.size();
    Statement st{};
    st.kind = StatementKind::Pieces;
    rule.statements.push_back(st);
    const std::string& w = word.text;
    if (w == "split" || w == "repeat") {
        const SourceLocation a = tokens_.peek().where;
        const std::string name = tokens_.expectIdentifier("an axis x, y or z after '" + w + "'");
        if (axisIndex(name) < 0) tokens_.fail(a, "expected an axis x, y or z after '" + w + "', found '" + name + "'");
        list.axis = std::uint8_t(axisIndex(name));
    }
    if (w == "split") {
        list.kind = PiecesKind::Split;
        parseSplitList(rule, scope, pieces, readsScope);
    } else if (w == "repeat" || w == "copy") {
        if (w == "copy") {
            list.kind = PiecesKind::CopyCount;
            if (tokens_.peek().kind == TokenKind::Identifier && headerIndex_.count(tokens_.peek().text) &&
                !tokens_.peekSecond().is('('))
                tokens_.expected("the number of copies before the successor (copy N SUCCESSOR)");
        } else if (tokens_.peek().isWord("count")) {
            tokens_.take();
            list.kind = PiecesKind::RepeatCount;
        } else {
            list.kind = PiecesKind::RepeatSize;
            if (tokens_.peek().is('~')) {
                tokens_.take();
                list.floating = true;
            }
        }
        compileScalar(scope, list.arg[0]);
        readsScope = takeScopeFrameReads();
        parseSuccessorList(rule, scope, pieces, scope.form);
    } else if (w == "comp") {
        list.kind = PiecesKind::Comp;
        parseCompFaces(rule, scope, word, pieces);
    } else {
        parseLotPieces(rule, scope, word, list, pieces, readsScope);
    }
    if (pieces.empty()) tokens_.fail(word.where, "'" + w + "' needs at least one piece");
    if (g_.pieceLists.size() >= 65535) tokens_.fail(word.where, "too many split, repeat, comp and lot statements (at most 65535)");
    if (readsScope) insertScopeFrame(rule, at, pieces);
    storePieces(rule, readsScope ? at + 1 : at, list, pieces);
}

std::size_t Parser::openCopy(Rule& rule, const SourceLocation& at) {
    if (g_.pieceLists.size() >= 65535) tokens_.fail(at, "too many split, repeat, comp, lot and [ ] statements (at most 65535)");
    Statement st{};
    st.kind = StatementKind::Pieces;
    rule.statements.push_back(st);
    return rule.statements.size() - 1;
}

void Parser::closeCopy(Rule& rule, std::size_t at) {
    PieceList list;
    list.kind = PiecesKind::Copy;
    std::vector<Piece> pieces(1);
    pieces[0].begin = std::uint32_t(at + 1);
    pieces[0].end = std::uint32_t(rule.statements.size());
    storePieces(rule, at, list, pieces);
}

void Parser::parseCopy(Rule& rule, BodyScope& scope) {
    const Token open = tokens_.take();  // [
    const std::size_t at = openCopy(rule, open.where);
    BodyScope inner = scope;
    while (!tokens_.peek().is(']')) {
        if (tokens_.peek().kind == TokenKind::End)
            tokens_.expected("']' to close the [ block opened at line " + std::to_string(open.where.line));
        parseStatement(rule, inner);
        if (rule.statements.size() > kMaxStatements) tokens_.fail(open.where, "rule " + rule.name + " has more than 2^20 statements");
    }
    tokens_.take();
    closeCopy(rule, at);
}

void Parser::storePieces(Rule& rule, std::size_t at, PieceList& list, std::vector<Piece>& pieces) {
    for (std::size_t k = 0; k < pieces.size(); ++k) {  // Piece::first: the first with the same statements
        std::size_t j = 0;
        while (pieces[j].begin != pieces[k].begin || pieces[j].end != pieces[k].end) ++j;
        pieces[k].first = std::uint16_t(std::min<std::size_t>(j, 65535));
    }
    list.first = std::uint32_t(g_.pieces.size());
    list.count = std::uint32_t(pieces.size());
    g_.pieces.insert(g_.pieces.end(), pieces.begin(), pieces.end());
    rule.statements[at].slot = std::uint16_t(g_.pieceLists.size());
    rule.statements[at].end = std::uint32_t(rule.statements.size());
    g_.pieceLists.push_back(list);
}

}  // namespace shapevo::grammar_detail
