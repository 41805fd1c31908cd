// The form of a `.pcg` graph file (grammars/pcg/README.md) as read, before any meaning is given
// to it: declarations, nodes, edges and blocked ports, each with its place in the file.
// Expressions stay token lists (read with the shapevo grammar's own lexer, grammar/lexer.hpp) and
// are written back as text by the translation, so `.pcg` expressions and priors are exactly the
// shapevo language's. A statement ends at the end of its line unless a bracket is still open.
#pragma once
#include <string>
#include <vector>

#include "grammar/lexer.hpp"
#include "grammar/translation.hpp"

namespace shapevo::pcg {

/// An expression (or a prior, or a split size) as the tokens the file wrote.
struct Expr {
    std::vector<Token> tokens;
    Location where;  ///< its first token
};

/// One argument of a node: `NAME: EXPR` or, positional, `EXPR` (name empty).
struct Arg {
    std::string name;
    Expr value;
    Location where;  ///< the name, or the value for a positional argument
};

struct AttrDecl {   ///< `attr NAME = EXPR`: a constant, overridable like a .grammar attr
    std::string name;
    Expr value;
    Location where;
};

struct ParamDecl {  ///< `param NAME = PRIOR`: an evolvable graph parameter
    std::string name;
    Expr prior;
    Location where;
};

struct GateDecl {   ///< `in NAME : TYPE` / `out NAME : TYPE`: a port of the graph as a node
    std::string name;
    bool input = true;
    std::string type;  ///< volume, flat or entity
    Location where, typeAt;
};

struct NodeDecl {   ///< `node ID = OP(ARGS)` or `node ID = include "FILE"(ARGS)`
    std::string id;
    std::string op;      ///< empty for an include
    std::string file;    ///< the include's file, as written
    std::vector<Arg> args;
    Location where;      ///< the id
    Location opAt;       ///< the op (or the include's file)
};

/// `NODE.PORT`, or `NODE` alone (its only port on that side).
struct PortRef {
    std::string node, port;
    Location where;
};

struct EdgeDecl {   ///< one `SRC.PORT -> DST.PORT` (a line with several destinations gives several)
    PortRef from, to;
};

struct PcgFile {
    std::string path;
    std::string name;  ///< `graph NAME`
    Location nameAt;
    std::vector<AttrDecl> attrs;
    std::vector<AttrDecl> carried;  ///< `carry NAME = VALUE`: graph attribute declarations with defaults
    std::vector<ParamDecl> params;
    std::vector<GateDecl> gates;
    std::vector<NodeDecl> nodes;
    std::vector<EdgeDecl> edges;
    std::vector<PortRef> blocked;
};

/// Read a `.pcg` file's text. @throw InputError at path:line:column for anything malformed.
PcgFile readPcg(const std::string& text, const std::string& path);

}  // namespace shapevo::pcg
