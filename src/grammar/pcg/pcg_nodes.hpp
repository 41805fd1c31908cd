// The `.pcg` node table: one entry per node operation, with its input and output ports (typed
// volume / flat / entity), its arguments and how it writes shapevo-language text
// (docs/pcg-format.md lists them). Most ports are single ports (one entity per round); the
// collective nodes (order_by, reverse, shuffle, amount_filter, filter) have collective ports
// (PCGR §3.2: the whole list at once): an edge into one is a `send`, a chain of them one
// `gather` (pcg_collective.cpp) whose steps their writers write and whose routes the last one's.
#pragma once
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace shapevo::pcg {

enum class PortType {
    Volume,  ///< a volume scope
    Flat,    ///< a flat scope (a lot, a face)
    Entity,  ///< either (an input of this type accepts both)
    Same,    ///< an output: whatever the node's input is
};
const char* portTypeName(PortType t);

struct PortSpec {
    const char* name;
    PortType type;
    bool collective = false;  ///< a list port: the whole list at once (drawn square)
};

enum class ArgKind {
    Expr,   ///< a shapevo expression, copied through as text
    Axis,   ///< x, y or z
    Word,   ///< one of ArgSpec::words
    Sizes,  ///< the rest of the arguments: split sizes (EXPR, 'EXPR, ~EXPR), one output each
    Keys,   ///< the rest of the arguments: sort keys (EXPR, EXPR desc), no outputs of their own
};

/// What a node does with lists: nothing (single ports), a step of a gather, or its route.
enum class Collect {
    None,   ///< single ports: each entity runs the node on its own
    Step,   ///< a collective input and output `out`: a step (order by, reverse, shuffle)
    Route,  ///< a collective input and routed outputs: the gather's last word (keep first, where)
};

struct ArgSpec {
    const char* name;
    ArgKind kind;
    const char* fallback;       ///< the text used when it is left out; nullptr: required; "": optional, none
    const char* words = nullptr;  ///< ArgKind::Word: the allowed words, space separated
};

/// What a node's writer sees: its arguments as text and the text of what follows each output.
class NodeWriter {
public:
    virtual ~NodeWriter() = default;
    /// Argument `k` of the op's ArgSpec list as text ("" when optional and left out).
    virtual const std::string& arg(std::size_t k) const = 0;
    /// Split sizes (ArgKind::Sizes), one per output; sort keys (ArgKind::Keys).
    virtual const std::vector<std::string>& sizes() const = 0;
    /// One line of shapevo text at the node's place.
    virtual void line(const std::string& text) = 0;
    /// Whether output `port` leads anywhere (connected and not blocked).
    virtual bool flows(std::size_t port) const = 0;
    /// Write what follows output `port`, here (nothing for a leaf or a blocked port).
    virtual void flow(std::size_t port) = 0;
    /// The name of a rule that starts a new gene (declaring the graph's params again) and runs
    /// what follows output `port` there: for a `child` slot the node writes.
    virtual std::string childRule(std::size_t port) = 0;
    /// A located error at the node.
    [[noreturn]] virtual void fail(const std::string& message) const = 0;
};

struct NodeOp {
    const char* name;
    const char* summary;              ///< for messages and the README table
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;    ///< with ArgKind::Sizes: one output per size, named slice1, slice2, ...
    std::vector<ArgSpec> args;
    void (*write)(NodeWriter&);
    bool wayOut = false;              ///< may stop what passes (an `if`, a `chance`): a cycle through it may end
    Collect collect = Collect::None;  ///< Step / Route: `write` writes the gather's step line / its route
    bool newGene = false;             ///< what follows it runs in a gene of its own (a `chance`)
};

/// Every node operation, in the README's order.
std::span<const NodeOp> nodeOps();
const NodeOp* findNodeOp(const std::string& name);
/// "box, cylinder, ..." for messages.
std::string nodeOpNames();

}  // namespace shapevo::pcg
