// Lists (PCGR's collective operations, grammars/README.md "Lists"): `send NAME` and
// `gather NAME { STEPS }`. A rule body that gathers starts with an Open statement naming its
// gathers (found by a scan of the body's tokens before it is compiled), so derive opens their
// collections before anything the invocation does; each gather block compiles into a Gather
// statement (where its frame is taken) followed by its routes' successors, and its steps into
// Grammar::listOps. Every send is checked here to reach a gather of the same gene: of its own
// body or of a body that runs it inline, never through `child`.
#include "base/input_error.hpp"
#include "grammar/parser_state.hpp"

namespace shapevo::grammar_detail {

namespace {
constexpr const char* kStepWords = "a list operation (order by, reverse, shuffle, let NAME = min|max|avg|sum(E), group by, "
                                   "cluster, unify, merge, ungroup) or a route (each, keep first, where)";
/// `unify` without `within`: edges closer than this (world units) touch.
constexpr float kDefaultUnifyTolerance = 0.001f;
/// Where a gather's rule body ends: true at its top-level `}` (or the end of the file).
bool endsBody(const Token& t, int depth) { return t.kind == TokenKind::End || (depth == 0 && (t.is('}') || t.is(']'))); }
}  // namespace

std::uint16_t Parser::listName(const std::string& name, const SourceLocation& at) {
    for (std::size_t i = 0; i < g_.listNames.size(); ++i)
        if (g_.listNames[i] == name) return std::uint16_t(i);
    if (g_.listNames.size() >= 65535) tokens_.fail(at, "too many list names (at most 65535)");
    g_.listNames.push_back(name);
    return std::uint16_t(g_.listNames.size() - 1);
}

bool Parser::bodyGathers(std::size_t body) {
    const std::size_t resume = tokens_.mark();
    tokens_.seek(body);
    bool found = false;
    for (int depth = 0; !endsBody(tokens_.peek(), depth);) {
        const Token t = tokens_.take();
        if (t.is('{') || t.is('[')) ++depth;
        if (t.is('}') || t.is(']')) --depth;
        if (depth == 0 && t.isWord("gather")) found = true;
    }
    tokens_.seek(resume);
    return found;
}

void Parser::parseBody(Rule& rule, BodyScope& scope, const std::string& closes) {
    GatheringBody body;
    body.first = std::uint32_t(g_.gathers.size());
    const std::size_t start = tokens_.mark();
    for (int depth = 0; !endsBody(tokens_.peek(), depth);) {
        const std::size_t at = tokens_.mark();
        const Token t = tokens_.take();
        if (t.is('{') || t.is('[')) ++depth;
        if (t.is('}') || t.is(']')) --depth;
        if (depth != 0 || !t.isWord("gather") || tokens_.peek().kind != TokenKind::Identifier) continue;
        if (g_.gathers.size() >= 65535) tokens_.fail(t.where, "too many gather blocks (at most 65535)");
        Gather gather;
        gather.list = listName(tokens_.peek().text, tokens_.peek().where);
        gather.where = t.where;
        g_.gathers.push_back(gather);
        body.tokens.push_back(at);
    }
    tokens_.seek(start);
    if (body.tokens.empty()) return parseBlock(rule, scope, closes);
    Statement open{};
    open.kind = StatementKind::Open;
    open.slot = std::uint16_t(body.first);
    open.end = std::uint32_t(body.tokens.size());
    rule.statements.push_back(open);
    g_.hasLists = true;
    bodies_.push_back(std::move(body));
    parseBlock(rule, scope, closes);
    bodies_.pop_back();
}

void Parser::parseSend(Rule& rule, const Token& word) {
    const SourceLocation at = tokens_.peek().where;
    const std::string name = tokens_.expectIdentifier("a list name after 'send'");
    for (auto b = bodies_.rbegin(); b != bodies_.rend(); ++b)
        for (std::size_t k = b->closed; k < b->tokens.size(); ++k)
            if (g_.listNames[g_.gathers[b->first + k].list] == name) {
                Statement s{};
                s.kind = StatementKind::Send;
                s.slot = g_.gathers[b->first + k].list;
                rule.statements.push_back(s);
                return;
            }
    (void)word;
    const std::string message = "'send " + name + "' has no 'gather " + name + "' to go to: a send goes to a gather of the "
                                "rule it is in or of a rule that runs it inline (a split, comp or lot successor, or a call), "
                                "never to another gene ('child' starts one), nor from a gather's route to that gather or an "
                                "earlier one";
    if (!deferSends_) tokens_.fail(at, message);
    deferredSends_.push_back({currentRule_, at, message});
    Statement s{};  // never run: the rule is only used inline, or the grammar is refused
    s.kind = StatementKind::Send;
    s.slot = listName(name, at);
    rule.statements.push_back(s);
}

void Parser::checkDeferredSends() {
    if (deferredSends_.empty()) return;
    std::vector<bool> gene(g_.rules.size(), false);
    gene[g_.start] = true;
    for (const Rule& r : g_.rules)
        for (const Slot& slot : r.slots)
            for (std::uint16_t id : slot.rules) gene[id] = true;
    for (const DeferredSend& d : deferredSends_)
        if (gene[d.rule]) tokens_.fail(d.where, d.message);
}

void Parser::parseGather(Rule& rule, BodyScope& scope) {
    const std::size_t position = tokens_.mark();
    const Token word = tokens_.take();
    if (tokens_.peek().kind != TokenKind::Identifier) tokens_.expected("a list name after 'gather'");
    if (bodies_.empty() || bodies_.back().next >= bodies_.back().tokens.size() ||
        bodies_.back().tokens[bodies_.back().next] != position)
        tokens_.fail(word.where, "'gather' goes at the top level of a rule's body (not inside a block, a branch, a "
                                 "successor or [ ]): it runs once per invocation of the rule");
    // by index: a route's successor may call a rule that gathers, which pushes onto bodies_
    const std::size_t b = bodies_.size() - 1;
    const std::uint32_t index = bodies_[b].first + std::uint32_t(bodies_[b].next);
    const std::string name = tokens_.expectIdentifier("a list name after 'gather'");
    const SourceLocation open = tokens_.peek().where;
    tokens_.expect('{', "after 'gather " + name + "' (gather NAME { OPERATIONS ROUTE })");
    Statement st{};
    st.kind = StatementKind::Gather;
    st.slot = std::uint16_t(index);
    const std::size_t at = rule.statements.size();
    rule.statements.push_back(st);
    BodyScope inner = scope;  // aggregates add their names for the steps after them
    g_.gathers[index].firstOp = std::uint32_t(g_.listOps.size());
    const std::size_t closedBefore = bodies_[b].closed;
    bool routed = false;
    while (!tokens_.peek().is('}')) {
        if (routed) tokens_.expected("'}' to close 'gather " + name + "': its route is its last step");
        const Token step = tokens_.take();
        ListOp op;
        if (step.isWord("order") || step.isWord("group")) {
            parseKeys(inner, step, step.isWord("order") ? ListOpKind::OrderBy : ListOpKind::GroupBy);
            continue;
        }
        if (step.isWord("reverse")) {
            op.kind = ListOpKind::Reverse;
        } else if (step.isWord("cluster")) {
            op.kind = ListOpKind::Cluster;
            compileScalar(inner, op.expr[0]);
            if (!tokens_.peek().isWord("by")) tokens_.expected("'by' after 'cluster K' (cluster K by POINT, e.g. scope.origin)");
            tokens_.take();
            compileVector(inner, op.expr + 1);
            op.dims = std::uint8_t(exprs_.lastDims());
        } else if (step.isWord("unify")) {
            op.kind = ListOpKind::Unify;
            if (tokens_.peek().isWord("within")) {
                tokens_.take();
                compileScalar(inner, op.expr[0]);
            } else {
                op.expr[0] = constantExpression(kDefaultUnifyTolerance);
            }
        } else if (step.isWord("merge")) {
            op.kind = ListOpKind::Merge;
        } else if (step.isWord("ungroup")) {
            op.kind = ListOpKind::Ungroup;
        } else if (step.isWord("shuffle")) {
            op.kind = ListOpKind::Shuffle;
            compileScalar(inner, op.expr[0]);
        } else if (step.isWord("let")) {
            const SourceLocation nameAt = tokens_.peek().where;
            const std::string let = tokens_.expectIdentifier("a name after 'let'");
            if (isReservedName(let)) tokens_.fail(nameAt, "'" + let + "' is a reserved name and cannot name a let value");
            tokens_.expect('=', "after the name of the let value");
            const Token kind = tokens_.take();
            const char* kinds[] = {"min", "max", "avg", "sum"};
            int k = 0;
            while (k < 4 && !kind.isWord(kinds[k])) ++k;
            op.kind = ListOpKind::Aggregate;
            if (kind.isWord("raycast") || kind.isWord("facing")) {
                parseLookStep(inner, kind, index, op);
            } else if (kind.isWord("group")) {  // let NAME = group.index
                tokens_.expect('.', "after 'group' (let " + let + " = group.index: the number of the entity's group)");
                if (!tokens_.peek().isWord("index")) tokens_.expected("'index' after 'group.'");
                tokens_.take();
                op.detail = std::uint8_t(AggregateKind::GroupIndex);
                op.dims = 1;
            } else {
                if (k == 4)
                    tokens_.fail(kind.where, "expected an aggregate min, max, avg or sum, or group.index, raycast(...) or facing(...), after 'let " +
                                                 let + " =' in a gather, found " + kind.describe());
                tokens_.expect('(', "after '" + kind.text + "' (an aggregate of one expression per entity)");
                op.detail = std::uint8_t(k);
                compileVector(inner, op.expr);
                op.dims = std::uint8_t(exprs_.lastDims());
                tokens_.expect(')', "to close '" + kind.text + "('");
            }
            op.slot = allocateFrame(rule, op.dims, nameAt);
            Binding b;
            b.name = let;
            b.dims = op.dims;
            b.constant = false;
            b.index = op.slot;
            inner.bindings.push_back(b);
        } else if (step.isWord("each") || step.isWord("keep") || step.isWord("where")) {
            bodies_[b].closed = bodies_[b].next + 1;  // the routes' sends go past this gather
            parseRoute(rule, inner, step, op);
            routed = true;
        } else {
            tokens_.fail(step.where, "expected " + std::string(kStepWords) + " in 'gather " + name + "', found " + step.describe());
        }
        g_.listOps.push_back(op);
    }
    tokens_.take();
    if (!routed)
        tokens_.fail(open, "'gather " + name + "' has no route: end it with 'each : SUCCESSOR', 'keep first N : A | rest : B' "
                           "or 'where (CONDITION) : A | else : B'");
    bodies_[b].closed = closedBefore;
    ++bodies_[b].next;
    g_.gathers[index].ops = std::uint32_t(g_.listOps.size() - g_.gathers[index].firstOp);
    takeScopeFrameReads();  // the gather's expressions are evaluated per entity, with its frame written
    rule.statements[at].end = std::uint32_t(rule.statements.size());
}

void Parser::parseKeys(const BodyScope& scope, const Token& word, ListOpKind kind) {
    const bool order = kind == ListOpKind::OrderBy;
    if (!tokens_.peek().isWord("by")) tokens_.expected(order ? "'by' after 'order'" : "'by' after 'group' (group by E, ...)");
    tokens_.take();
    const std::size_t first = g_.listOps.size();
    do {
        if (g_.listOps.size() > first) tokens_.take();  // ,
        if (g_.listOps.size() - first >= 255) tokens_.fail(word.where, "'" + word.text + " by' takes at most 255 keys");
        ListOp key;
        key.kind = kind;
        compileScalar(scope, key.expr[0]);
        if (order && (tokens_.peek().isWord("asc") || tokens_.peek().isWord("desc"))) key.detail = tokens_.take().text == "desc";
        g_.listOps.push_back(key);
    } while (tokens_.peek().is(','));
    g_.listOps[first].keys = std::uint8_t(g_.listOps.size() - first);
}

void Parser::parseLookStep(const BodyScope& scope, const Token& kind, std::uint32_t gather, ListOp& op) {
    const bool ray = kind.isWord("raycast");
    tokens_.expect('(', ray ? "after 'raycast' (raycast(+z, LIST))" : "after 'facing' (facing(LIST, DEGREES))");
    if (ray) {
        op.kind = ListOpKind::RayCast;
        bool negative = false;
        if (tokens_.peek().is('+') || tokens_.peek().is('-')) negative = tokens_.take().is('-');
        const Token axis = tokens_.take();
        const int a = axis.isWord("x") ? 0 : axis.isWord("y") ? 1 : axis.isWord("z") ? 2 : -1;
        if (a < 0) tokens_.fail(axis.where, "expected an axis of the entity's scope (x, y or z, with + or -) in 'raycast(', found " + axis.describe());
        op.detail = std::uint8_t(a + (negative ? 4 : 0));
        tokens_.expect(',', "after raycast's axis (raycast(+z, LIST))");
    } else {
        op.kind = ListOpKind::Facing;
    }
    // the list looked at: this gather's own, or one a later gather of the same body gathers
    const SourceLocation at = tokens_.peek().where;
    const std::string name = tokens_.expectIdentifier(std::string("a list name in '") + kind.text + "('");
    const GatheringBody& body = bodies_.back();
    op.other = g_.listNames[g_.gathers[gather].list] == name ? kOwnList : UINT32_MAX - 1;
    for (std::size_t k = body.next + 1; k < body.tokens.size() && op.other == UINT32_MAX - 1; ++k)
        if (g_.listNames[g_.gathers[body.first + k].list] == name) op.other = body.first + std::uint32_t(k);
    if (op.other == UINT32_MAX - 1)
        tokens_.fail(at, "'" + kind.text + "(" + name + ", ...)' looks at list " + name + ", which no gather of this rule after this "
                         "one gathers: it may look at its own list or at a later gather's (whose entities are all there by now)");
    if (!ray) {
        tokens_.expect(',', "after facing's list (facing(LIST, DEGREES))");
        compileScalar(scope, op.expr[0]);
        if (tokens_.peek().is(',')) {
            tokens_.take();
            if (!tokens_.peek().isWord("unoccluded")) tokens_.expected("'unoccluded' after facing's angle");
            tokens_.take();
            op.detail = 1;
        }
    }
    tokens_.expect(')', std::string("to close '") + kind.text + "('");
    op.dims = 1;
}

void Parser::parseRoute(Rule& rule, BodyScope& scope, const Token& word, ListOp& op) {
    const char* second = "rest";
    if (word.isWord("each")) {
        op.kind = ListOpKind::Each;
        second = nullptr;
    } else if (word.isWord("keep")) {
        op.kind = ListOpKind::KeepFirst;
        if (!tokens_.peek().isWord("first")) tokens_.expected("'first' after 'keep' (keep first N [from K] : A | rest : B)");
        tokens_.take();
        compileScalar(scope, op.expr[0]);
        if (tokens_.peek().isWord("from")) {
            tokens_.take();
            compileScalar(scope, op.expr[1]);
        } else {
            op.expr[1] = constantExpression(0.0f);
        }
    } else {
        op.kind = ListOpKind::Where;
        second = "else";
        tokens_.expect('(', "after 'where' (the condition goes in parentheses)");
        compileCondition(scope, op.expr[0]);
        tokens_.expect(')', "to close the condition");
    }
    takeScopeFrameReads();
    tokens_.expect(':', "after the route '" + word.text + "' (then its successor: a rule name, '{ statements }' or nil)");
    Piece piece;
    parseSuccessor(rule, scope, piece, ScopeForm::Unknown);
    op.begin[0] = piece.begin;
    op.end[0] = piece.end;
    op.begin[1] = op.end[1] = piece.end;
    if (second == nullptr || !tokens_.peek().is('|')) return;
    tokens_.take();
    if (!tokens_.peek().isWord(second)) tokens_.expected(std::string("'") + second + "' after '|' in the route '" + word.text + "'");
    tokens_.take();
    tokens_.expect(':', std::string("after '") + second + "'");
    Piece other;
    parseSuccessor(rule, scope, other, ScopeForm::Unknown);
    op.begin[1] = other.begin;
    op.end[1] = other.end;
}

}  // namespace shapevo::grammar_detail
