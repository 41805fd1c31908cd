// GraphGrammar: a 2D graph grammar file as read and compiled (graph-grammar README, section 1):
// host graphs (axioms), productions (a mother graph with match conditions, one or more weighted
// daughter options with their partial morphism and attribute expressions), global variables,
// derivation limits and the SVG preamble. Every expression is compiled and every name resolved;
// every id reference is checked. Positions in file order; file ids kept for messages only.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graph/expression.hpp"
#include "graph/host_graph.hpp"
#include "graph/value.hpp"

namespace shapevo::graph {

/// Where an element came from in the file, for messages: "production 'Grow', daughter vertex 12".
struct FilePlace {
    int line = 0, column = 0;
    std::int64_t id = 0;
};

/// A match condition on one attribute of a mother element (`attr`, `attrs`, globals visible).
struct MatchCondition {
    AttrKey key;
    CompiledExpression test;
    FilePlace place;
};

struct MotherVertex {
    Vec2 position;
    std::vector<MatchCondition> conditions;  // empty: a wildcard
    FilePlace place;
};

struct MotherEdge {
    int vertex1 = -1, vertex2 = -1;  // mother vertex indices; -1: a dangling end (matches any)
    bool directed = false;           // the host edge must run vertex1 -> vertex2
    std::vector<MatchCondition> conditions;
    FilePlace place;
};

/// One attribute of a daughter element: an expression evaluated for kept and new elements, or a
/// `.`-key copied verbatim into new elements only.
struct DaughterAttr {
    AttrKey key;
    bool verbatim = false;
    Value value;                    // verbatim
    CompiledExpression expression;  // !verbatim
    FilePlace place;
};

/// Names an element's expressions may read, bound to host elements (attr_requirements).
struct Requirement {
    std::string name;
    bool motherIsVertex = true;
    int motherIndex = 0;
};

struct DaughterVertex {
    Vec2 position;
    int mother = -1;                  // the mother vertex it is the image of (mapping), or -1: new
    std::vector<DaughterAttr> attrs;  // in file order
    std::optional<CompiledExpression> newX, newY, newPos;
    std::vector<Requirement> requirements;  // its own (not `all`)
    FilePlace place;
};

struct DaughterEdge {
    int vertex1 = -1, vertex2 = -1;  // daughter vertex indices; -1 dangling
    int mother = -1;                 // the mother edge it is the image of, or -1: new
    std::vector<DaughterAttr> attrs;
    std::vector<Requirement> requirements;
    FilePlace place;
};

/// A variable of an option's var_calc_instructions.
struct OptionVariable {
    std::string name;
    bool perRun = false;  // `run`: once per derivation (globals visible); else per application
    CompiledExpression expression;
    FilePlace place;
};

struct ProductionOption {
    std::int64_t weight = 1;
    bool oldest = false;  // conditions: {generation: oldest}
    std::vector<DaughterVertex> vertices;
    std::vector<DaughterEdge> edges;
    std::vector<Requirement> requirementsForAll;
    std::vector<OptionVariable> variables;  // file order
    /// Slot layout of this option's element expressions (expression.hpp NameSlots); the first
    /// `sharedSlots` are the same for every element, then each element's own requirements.
    NameSlots slots;
    std::size_t sharedSlots = 0;
    FilePlace place;
};

struct Production {
    std::string name;
    int priority = 0;
    std::optional<CompiledExpression> geometricOrdering;
    struct Vector {
        std::string name;
        int from = -1, to = -1;  // mother vertex indices; from = -1: a point vector (host position of `to`)
    };
    std::vector<Vector> vectors;
    std::vector<MotherVertex> motherVertices;
    std::vector<MotherEdge> motherEdges;
    std::vector<ProductionOption> options;
    FilePlace place;
};

struct GlobalVariable {
    std::string name;
    CompiledExpression expression;
    FilePlace place;
};

/// One filter of `svg.preamble`, written into the SVG's <defs>.
struct SvgFilter {
    std::string id;
    struct Primitive {
        std::string tag;  // e.g. feGaussianBlur
        std::vector<std::pair<std::string, std::string>> attributes;  // name (as given), value as text
    };
    std::vector<Primitive> primitives;
};

struct GraphGrammar {
    std::string path;
    std::string source;  // the file's text (a run stores it; a genome file hashes it)
    AttrNames names;
    struct Host {
        std::string name;
        HostGraph graph;
    };
    std::vector<Host> hosts;
    std::vector<Production> productions;  // file order
    std::vector<GlobalVariable> globals;  // file order
    /// options.max_derivations: per priority (priority, limit) and `all` (0: no global limit).
    std::vector<std::pair<int, std::int64_t>> priorityLimits;
    std::int64_t globalLimit = 0;
    std::vector<SvgFilter> filters;
    /// Keys the engine itself uses, interned when the file is read.
    struct Keys {
        AttrKey generation, directed, svgTag, helperNode;
    } keys{};
};

}  // namespace shapevo::graph
