// ReaderContext: what the graph grammar reader shares between its files (read_graph_grammar.cpp,
// read_production.cpp) — the file's path, the one id table spanning the whole file, located
// errors, scalar conversions and expression compilation with messages that name the place.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "graph/graph_grammar.hpp"
#include "graph/yaml_tree.hpp"

namespace shapevo::graph::reading {

/// Bounds on names, so that reading (and setting up a derivation) stays near linear in the
/// file's size whatever it holds: a name is looked up by a scan of its place's names, and every
/// option sees every global variable.
inline constexpr std::size_t kMaxGlobalVariables = 1000;
/// Vectors, requirements for all and variables of one option; own requirements of one element.
inline constexpr std::size_t kMaxOptionNames = 1000;
/// The names every production's conditions and every option's expressions see, summed.
inline constexpr std::size_t kMaxNamesInScopes = 2'000'000;

/// Where a message points: the node, and what the node is ("production 'Grow', daughter vertex 12").
struct Place {
    const YamlNode* node;
    std::string what;
};

class ReaderContext {
public:
    /// `source`: the file's text (may be empty), to place an expression's error at its column.
    ReaderContext(std::string path, AttrNames& names, std::string_view source = {})
        : path_(std::move(path)), names_(names), source_(source) {}

    [[noreturn]] void fail(const YamlNode& at, const std::string& message) const;
    [[noreturn]] void fail(const Place& at, const std::string& message) const;

    const YamlNode& mapping(const YamlNode& n, const std::string& what) const;
    const YamlNode& sequence(const YamlNode& n, const std::string& what) const;
    const YamlNode& required(const YamlNode& map, std::string_view key, const std::string& what) const;
    /// Refuses a key not in `allowed` (a typo in a key would otherwise be ignored silently).
    void onlyKeys(const YamlNode& map, std::initializer_list<std::string_view> allowed, const std::string& what) const;
    std::string keyText(const YamlNode& key, const std::string& what) const;
    std::int64_t integer(const YamlNode& n, const std::string& what) const;
    /// A file id, declared or referred to: a YAML integer only (the original's ids are ints, and
    /// '7' never equals 7 there, so a quoted id is an error, not an alias of 7).
    std::int64_t id(const YamlNode& n, const std::string& what) const;
    /// A number given as a number or as a string ('-4', '6.93'), as Python's float() reads it.
    double number(const YamlNode& n, const std::string& what) const;
    /// A scalar as plain data (host graph attributes).
    Value plainValue(const YamlNode& n, const std::string& what) const;
    /// A scalar's Python str() (the text an expression place compiles: 'True' for a YAML bool).
    std::string expressionText(const YamlNode& n, const std::string& what) const;

    /// A graph's vertex or edge entry ({id, attr} or {id, vertex1, vertex2, attr}): checked, its id
    /// declared; returns the id node and sets `elementWhat` ("<graph>, vertex 12") for messages.
    const YamlNode& elementEntry(const YamlNode& entry, bool vertex, const std::string& graphWhat, std::string& elementWhat);
    /// Registers a file id (graph, vertex, edge, production, option, mapping); a second use of
    /// one id is an error naming both places.
    void declareId(const YamlNode& idNode, const std::string& what);
    /// Counts the `names` one more place (a production's conditions, an option) sees against
    /// kMaxNamesInScopes; an error at `at` past it.
    void countScope(std::size_t names, const YamlNode& at, const std::string& what);
    /// Compiles an expression; an error names the place and the column inside the expression.
    CompiledExpression compile(const YamlNode& n, const NameSlots& slots, const std::string& what) const;

    FilePlace filePlace(const YamlNode& n, std::int64_t id = 0) const { return FilePlace{n.line, n.column, id}; }
    const std::string& path() const { return path_; }
    AttrNames& names() { return names_; }

private:
    /// "line:column" of byte `offset` of the expression `text` that node `n` holds, if the source
    /// shows the text there unchanged (one line, no escapes); "" otherwise.
    std::string placeInside(const YamlNode& n, const std::string& text, std::size_t offset) const;

    std::string path_;
    AttrNames& names_;
    std::string_view source_;
    std::size_t scopeNames_ = 0;
    std::map<std::int64_t, std::pair<int, std::string>> ids_;  // id -> line, what
};

/// An id node for a message: its integer, or its text shortened (not an id yet: the error says so).
std::string idText(const YamlNode& n);
/// Python's truth of a scalar ('False' and '0' are truthy strings; a collection is truthy).
bool truthyScalar(const YamlNode& n);
/// A vertex whose attr has a truthy `.helper_node`: an editor placeholder, dropped on load (its
/// edges' ends dangle). One rule for host, mother and daughter graphs.
bool isHelperVertex(const YamlNode& vertex);

/// Reads one production (read_production.cpp); `globals` are the global variables' names.
Production readProduction(ReaderContext& context, const std::string& name, const YamlNode& node,
                          const std::vector<std::string>& globals);
/// Reads one option of a production (read_option.cpp).
ProductionOption readOption(ReaderContext& context, const YamlNode& node, const std::string& production, const Production& p,
                            std::int64_t motherGraphId, const std::map<std::int64_t, int>& motherVertexIds,
                            const std::map<std::int64_t, int>& motherEdgeIds, const std::vector<std::string>& globals);
/// Reads a host graph (plain attributes, positions, generations).
HostGraph readHostGraph(ReaderContext& context, const std::string& name, const YamlNode& node, const GraphGrammar::Keys& keys);

}  // namespace shapevo::graph::reading
