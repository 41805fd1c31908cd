// Reading a `.pcg` file into its form (pcg_syntax.hpp) with the shapevo grammar's lexer: line by
// line statements (`graph`, `attr`, `param`, `in`, `out`, `node`, `block`, edges), each error at
// file:line:column.
#include <set>

#include "base/input_error.hpp"
#include "grammar/pcg/pcg_syntax.hpp"

namespace shapevo::pcg {

namespace reader_detail {

constexpr std::size_t kMaxStatements = 100000;  // a limit a hand-written graph never meets

bool opens(const Token& t) { return t.is('(') || t.is('[') || t.is('{'); }
bool closes(const Token& t) { return t.is(')') || t.is(']') || t.is('}'); }

class Reader {
public:
    Reader(const std::string& text, const std::string& path) : in_(text, path), path_(path) {}

    PcgFile read() {
        PcgFile f;
        f.path = path_;
        std::size_t statements = 0;
        while (in_.peek().kind != TokenKind::End) {
            if (++statements > kMaxStatements) in_.fail(in_.peek().where, "too many statements (at most 100000)");
            const Token t = in_.peek();  // a copy: peekSecond() may move the tokens
            if (t.kind != TokenKind::Identifier)
                in_.expected("a statement (graph, attr, carry, param, in, out, node, block or an edge SRC.PORT -> DST.PORT)");
            if (t.isWord("graph") && in_.peekSecond().kind == TokenKind::Identifier) readGraph(f);
            else if (t.isWord("attr") && in_.peekSecond().kind == TokenKind::Identifier) readAttr(f, f.attrs);
            else if (t.isWord("carry") && in_.peekSecond().kind == TokenKind::Identifier) readAttr(f, f.carried);
            else if (t.isWord("param") && in_.peekSecond().kind == TokenKind::Identifier) readParam(f);
            else if ((t.isWord("in") || t.isWord("out")) && in_.peekSecond().kind == TokenKind::Identifier) readGate(f);
            else if (t.isWord("node") && in_.peekSecond().kind == TokenKind::Identifier) readNode(f);
            else if (t.isWord("block") && in_.peekSecond().kind == TokenKind::Identifier) readBlock(f);
            else readEdge(f);
        }
        if (f.name.empty()) throw InputError(path_, "1:1", "no graph name: a .pcg file starts with `graph NAME`");
        return f;
    }

private:
    Location at(const Token& t) const { return {path_, t.where.line, t.where.column}; }

    std::string name(const std::string& what, Location& where) {
        where = at(in_.peek());
        return in_.expectIdentifier(what);
    }

    /// An expression that ends at the end of its line (unless a bracket is open).
    Expr lineExpression(const std::string& what) {
        Expr e;
        if (in_.peek().kind == TokenKind::End || in_.peek().where.line != last_) in_.expected(what);
        e.where = at(in_.peek());
        int depth = 0;
        while (in_.peek().kind != TokenKind::End && (depth > 0 || in_.peek().where.line == last_)) {
            const Token t = in_.take();
            depth += opens(t) ? 1 : closes(t) ? -1 : 0;
            if (depth < 0) in_.fail(t.where, "unbalanced '" + t.text + "'");
            last_ = t.where.line;
            e.tokens.push_back(t);
        }
        if (depth > 0) in_.expected("a closing bracket");
        return e;
    }

    /// An argument's expression: up to a ',' or ')' outside brackets.
    Expr argExpression() {
        Expr e;
        e.where = at(in_.peek());
        int depth = 0;
        while (true) {
            const Token& t = in_.peek();
            if (t.kind == TokenKind::End) in_.expected("')' closing the arguments");
            if (depth == 0 && (t.is(',') || t.is(')'))) break;
            depth += opens(t) ? 1 : closes(t) ? -1 : 0;
            e.tokens.push_back(in_.take());
        }
        if (e.tokens.empty()) in_.expected("an argument");
        return e;
    }

    Token take() {
        Token t = in_.take();
        last_ = t.where.line;
        return t;
    }

    void readGraph(PcgFile& f) {
        const Token kw = take();
        if (!f.name.empty()) in_.fail(kw.where, "a second `graph` statement (the graph is named once)");
        f.name = name("a graph name", f.nameAt);
        last_ = f.nameAt.line;
    }

    /// `attr NAME = VALUE` or `carry NAME = VALUE` into `into`.
    void readAttr(PcgFile& f, std::vector<AttrDecl>& into) {
        (void)f;
        take();
        AttrDecl a;
        a.name = name("an attr name", a.where);
        last_ = a.where.line;
        expectSameLine('=', "after the attr name");
        a.value = lineExpression("a value after '='");
        into.push_back(std::move(a));
    }

    void readParam(PcgFile& f) {
        take();
        ParamDecl p;
        p.name = name("a parameter name", p.where);
        last_ = p.where.line;
        expectSameLine('=', "after the parameter name");
        p.prior = lineExpression("a prior after '=' (uniform(a, b), normal(mu, s) in [lo, hi], int(a, b), choice(...))");
        f.params.push_back(std::move(p));
    }

    void readGate(PcgFile& f) {
        GateDecl g;
        g.input = take().text == "in";
        g.name = name("a gate name", g.where);
        last_ = g.where.line;
        expectSameLine(':', "after the gate name (in NAME : volume|flat|entity)");
        g.type = name("a port type (volume, flat or entity)", g.typeAt);
        last_ = g.typeAt.line;
        f.gates.push_back(std::move(g));
    }

    void expectSameLine(char punct, const std::string& context) {
        if (in_.peek().where.line != last_ && in_.peek().kind != TokenKind::End) in_.expected(std::string("'") + punct + "' " + context);
        in_.expect(punct, context);
    }

    void readNode(PcgFile& f) {
        take();
        NodeDecl n;
        n.id = name("a node id", n.where);
        last_ = n.where.line;
        expectSameLine('=', "after the node id (node ID = OP(ARGS))");
        if (in_.peek().isWord("include") && in_.peekSecond().kind == TokenKind::String) {
            take();
            n.opAt = at(in_.peek());
            n.file = take().text;
            if (n.file.empty()) in_.fail({n.opAt.line, n.opAt.column}, "an include names no file");
        } else {
            n.op = name("a node operation (box, split, if, ..., or include \"FILE.pcg\")", n.opAt);
            last_ = n.opAt.line;
        }
        if (in_.peek().is('(') && in_.peek().where.line == last_) {
            take();
            while (!in_.peek().is(')')) {
                Arg a;
                a.where = at(in_.peek());
                if (in_.peek().kind == TokenKind::Identifier && in_.peekSecond().is(':')) {
                    a.name = in_.take().text;
                    in_.take();
                }
                a.value = argExpression();
                n.args.push_back(std::move(a));
                if (in_.peek().is(',')) in_.take();
                else if (!in_.peek().is(')')) in_.expected("',' or ')' after an argument");
            }
            take();
        }
        f.nodes.push_back(std::move(n));
    }

    PortRef portRef(const std::string& what) {
        PortRef r;
        r.node = name(what, r.where);
        last_ = r.where.line;
        if (in_.peek().is('.') && in_.peek().where.line == last_) {
            take();
            Location ignored;
            r.port = name("a port name after '.'", ignored);
            last_ = ignored.line;
        }
        return r;
    }

    void readBlock(PcgFile& f) {
        take();
        f.blocked.push_back(portRef("a port to block (NODE.PORT)"));
        while (in_.peek().is(',') && in_.peek().where.line == last_) {
            take();
            f.blocked.push_back(portRef("a port to block (NODE.PORT)"));
        }
    }

    void readEdge(PcgFile& f) {
        const PortRef from = portRef("a statement or an edge SRC.PORT -> DST.PORT");
        const Token dash = in_.peek();  // a copy: peekSecond() may move the tokens
        if (!(dash.is('-') && in_.peekSecond().is('>') && dash.where.line == last_))
            in_.expected("'->' after " + from.node + (from.port.empty() ? "" : "." + from.port) +
                         " (statements: graph, attr, carry, param, in, out, node, block; edges: SRC.PORT -> DST.PORT)");
        take();
        take();
        bool first = true;
        while (first || (in_.peek().is(',') && in_.peek().where.line == last_)) {
            if (!first) take();
            first = false;
            if (in_.peek().where.line != last_ && in_.peek().kind != TokenKind::End) in_.expected("a destination port after '->'");
            f.edges.push_back({from, portRef("a destination port (NODE.PORT)")});
        }
    }

    TokenStream in_;
    std::string path_;
    int last_ = 0;  ///< the line of the last token taken
};

}  // namespace reader_detail

using namespace reader_detail;

PcgFile readPcg(const std::string& text, const std::string& path) { return Reader(text, path).read(); }

}  // namespace shapevo::pcg
