// buildPcgGraph (pcg_graph.hpp): reading the main file and its includes into one graph of
// instances, resolving ops, arguments and port references, then the whole-graph checks.
#include "grammar/pcg/pcg_graph.hpp"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "base/input_error.hpp"
#include "grammar/pcg/pcg_expression_text.hpp"
#include "grammar/pcg/pcg_syntax.hpp"

namespace shapevo::pcg {

namespace fs = std::filesystem;

namespace graph_detail {

constexpr std::size_t kMaxIncludeDepth = 32;
constexpr std::size_t kMaxNodes = 20000;  // every instance's nodes together

std::string at(const Location& l) { return std::to_string(l.line) + ":" + std::to_string(l.column); }
[[noreturn]] void failAt(const Location& l, const std::string& what) { throw InputError(l.file, at(l), what); }

std::string joined(const std::vector<std::string>& words) {
    std::string s;
    for (std::size_t k = 0; k < words.size(); ++k) s += (k ? ", " : "") + words[k];
    return s.empty() ? "none" : s;
}

std::optional<PortType> portType(const std::string& word) {
    if (word == "volume") return PortType::Volume;
    if (word == "flat") return PortType::Flat;
    if (word == "entity") return PortType::Entity;
    return std::nullopt;
}

/// What an id names inside one file: a node of the graph, or an include node (its instance's gates).
struct LocalNode {
    std::uint32_t node = 0;
    bool include = false;
    std::string what;  ///< "box", "include door.pcg"
    std::map<std::string, std::uint32_t> gateIn, gateOut;
    std::vector<std::string> inNames, outNames;  ///< in the subgraph's order
    Location where;
};
using Locals = std::map<std::string, LocalNode>;

class Builder {
public:
    explicit Builder(const std::string& mainPath) : mainDir_(fs::path(mainPath).parent_path()) {}

    FlatGraph build(const std::string& text, const std::string& path) {
        files_.push_back(readPcg(text, path));
        const PcgFile& f = files_.back();
        g_.name = f.name;
        g_.nameAt = f.nameAt;
        std::error_code ec;
        stack_.push_back(fs::weakly_canonical(fs::path(path), ec).string());
        g_.scopes.push_back({"", f.name, -1, {}});
        instance(f, "", {}, nullptr);
        const bool hasInput = std::any_of(g_.nodes.begin(), g_.nodes.end(), [](const FlatNode& n) { return n.mainInput; });
        if (!hasInput) failAt(f.nameAt, "graph " + f.name + " has no input gate: write `in NAME : volume` (it receives the start scope)");
        return std::move(g_);
    }

private:
    void instance(const PcgFile& f, const std::string& prefix, const std::map<std::string, std::string>& bound, LocalNode* asInclude) {
        std::string shownPrefix = prefix;
        for (std::size_t k; (k = shownPrefix.find("__")) != std::string::npos;) shownPrefix.replace(k, 2, "/");
        Renames rename;
        std::map<std::string, Location> names;
        auto declareName = [&](const std::string& name, const Location& where) {
            if (auto it = names.find(name); it != names.end())
                failAt(where, "'" + name + "' is declared twice (first at line " + std::to_string(it->second.line) + ")");
            names.emplace(name, where);
            if (!prefix.empty()) rename[name] = prefix + name;
        };
        for (const AttrDecl& a : f.attrs) declareName(a.name, a.where);
        for (const AttrDecl& a : f.carried) {
            if (!prefix.empty())
                failAt(a.where, "carried attribute '" + a.name + "' is declared in an included graph: declare carried attributes "
                                "in the main graph, which every included graph reads and sets by name");
            declareName(a.name, a.where);
            g_.carried.push_back({a.name, expressionText(a.value, rename), a.where});
        }
        for (const ParamDecl& p : f.params) declareName(p.name, p.where);
        for (const AttrDecl& a : f.attrs) {
            auto b = bound.find(a.name);
            g_.attrs.push_back({prefix + a.name, b != bound.end() ? b->second : expressionText(a.value, rename), a.where});
        }
        for (const ParamDecl& p : f.params) {
            auto b = bound.find(p.name);
            g_.values.push_back({prefix + p.name,
                                 b != bound.end() ? "let " + prefix + p.name + " = " + b->second
                                                  : "param " + prefix + p.name + " = " + expressionText(p.prior, rename),
                                 p.where});
        }
        Locals local;
        scope_ = std::uint32_t(g_.scopes.size() - 1);
        auto declare = [&](const std::string& id, const Location& where) {
            if (auto it = local.find(id); it != local.end())
                failAt(where, "node id '" + id + "' is used twice (first at line " + std::to_string(it->second.where.line) + ")");
        };
        for (const GateDecl& gate : f.gates) {
            declare(gate.name, gate.where);
            const std::optional<PortType> type = portType(gate.type);
            if (!type) failAt(gate.typeAt, "unknown port type '" + gate.type + "': expected volume, flat or entity");
            FlatNode n;
            n.gate = true;
            n.mainInput = prefix.empty() && gate.input;
            n.name = shownPrefix + gate.name;
            n.ident = prefix + gate.name;
            n.detail = std::string(gate.input ? "input" : "output") + " gate (" + gate.type + ")";
            n.inputs.push_back({"in", *type, false, true});
            n.outputs.push_back({"out", *type, false, true});
            n.where = gate.where;
            n.scope = scope_;
            LocalNode& l = local[gate.name];
            l.what = n.detail;
            l.node = addNode(std::move(n), gate.where);
            l.where = gate.where;
            if (asInclude) {
                (gate.input ? asInclude->gateIn : asInclude->gateOut)[gate.name] = l.node;
                (gate.input ? asInclude->inNames : asInclude->outNames).push_back(gate.name);
            }
            gateInput_.resize(g_.nodes.size());
            gateInput_[l.node] = gate.input;
        }
        for (const NodeDecl& d : f.nodes) {
            declare(d.id, d.where);
            LocalNode l;
            l.where = d.where;
            if (d.op.empty()) {
                l.include = true;
                l.what = "include " + d.file;
                include(f, d, prefix, rename, l);
            } else {
                l.node = opNode(d, prefix, shownPrefix, rename);
                l.what = d.op;
            }
            local.emplace(d.id, std::move(l));
        }
        for (const EdgeDecl& e : f.edges) {
            const auto [from, fromPort] = source(e.from, local);
            const auto [to, toPort] = destination(e.to, local);
            g_.edges.push_back({from, fromPort, to, toPort, e.from.where});
        }
        for (const PortRef& r : f.blocked) {
            const auto [node, output] = source(r, local);
            g_.nodes[node].outputs[output].blocked = true;
        }
    }

    std::uint32_t addNode(FlatNode n, const Location& where) {
        if (g_.nodes.size() >= kMaxNodes) failAt(where, "too many nodes (at most 20000 with every include expanded)");
        g_.nodes.push_back(std::move(n));
        return std::uint32_t(g_.nodes.size() - 1);
    }

    std::uint32_t opNode(const NodeDecl& d, const std::string& prefix, const std::string& shownPrefix, const Renames& rename) {
        const NodeOp* op = findNodeOp(d.op);
        if (!op) failAt(d.opAt, "unknown node operation '" + d.op + "': expected one of " + nodeOpNames() + " or include \"FILE.pcg\"");
        FlatNode n;
        n.op = op;
        n.name = shownPrefix + d.id;
        n.ident = prefix + d.id;
        n.where = d.where;
        n.detail = d.op;
        n.scope = scope_;
        for (const PortSpec& p : op->inputs) n.inputs.push_back({p.name, p.type, false, false, p.collective});
        resolveArgs(d, *op, rename, n);
        const bool slices = !op->args.empty() && op->args.back().kind == ArgKind::Sizes;
        if (slices)
            for (std::size_t k = 0; k < n.sizes.size(); ++k) n.outputs.push_back({"slice" + std::to_string(k + 1), PortType::Same});
        else
            for (const PortSpec& p : op->outputs) n.outputs.push_back({p.name, p.type, false, false, p.collective});
        if (!n.args.empty() && op->args.front().kind == ArgKind::Axis) n.detail += " " + n.args.front();
        return addNode(std::move(n), d.where);
    }

    void resolveArgs(const NodeDecl& d, const NodeOp& op, const Renames& rename, FlatNode& n) {
        std::vector<std::optional<std::string>> values(op.args.size());
        std::size_t positional = 0;
        bool named = false;
        for (const Arg& a : d.args) {
            std::size_t k = 0;
            if (a.name.empty()) {
                if (named) failAt(a.where, "a positional argument after a named one (" + std::string(op.name) + ")");
                if (positional >= op.args.size())
                    failAt(a.where, std::string(op.name) + " takes " + std::to_string(op.args.size()) + " argument" +
                                        (op.args.size() == 1 ? "" : "s") + ", this node gives " + std::to_string(d.args.size()));
                k = positional;
                if (op.args[k].kind == ArgKind::Sizes || op.args[k].kind == ArgKind::Keys) {
                    n.sizes.push_back(expressionText(a.value, rename));
                    continue;
                }
                ++positional;
            } else {
                named = true;
                while (k < op.args.size() && a.name != op.args[k].name) ++k;
                std::vector<std::string> known;
                for (const ArgSpec& s : op.args) known.push_back(s.name);
                if (k == op.args.size())
                    failAt(a.where, std::string(op.name) + " has no argument '" + a.name + "' (its arguments: " + joined(known) + ")");
                if (op.args[k].kind == ArgKind::Sizes) failAt(a.where, "split sizes are positional: split(x, 1, ~2, 1)");
                if (op.args[k].kind == ArgKind::Keys)
                    failAt(a.where, std::string(op.name) + " keys are positional: " + op.name + "(scope.size.y, scope.origin.x)");
            }
            const ArgSpec& spec = op.args[k];
            if (values[k]) failAt(a.where, "argument '" + std::string(spec.name) + "' of " + op.name + " is given twice");
            if (spec.kind == ArgKind::Axis || spec.kind == ArgKind::Word) {
                const std::string words = spec.kind == ArgKind::Axis ? "x y z" : spec.words;
                const bool one = a.value.tokens.size() == 1 && a.value.tokens[0].kind == TokenKind::Identifier;
                std::istringstream allowed(words);
                std::vector<std::string> list;
                bool ok = false;
                for (std::string w; allowed >> w;) {
                    list.push_back(w);
                    ok = ok || (one && a.value.tokens[0].text == w);
                }
                if (!ok)
                    failAt(a.value.where, "argument '" + std::string(spec.name) + "' of " + op.name + " is one of " + joined(list) +
                                              ", not '" + shortened(expressionText(a.value, {})) + "'");
                values[k] = a.value.tokens[0].text;
            } else {
                values[k] = expressionText(a.value, rename);
            }
        }
        for (std::size_t k = 0; k < op.args.size(); ++k) {
            const ArgSpec& spec = op.args[k];
            if (spec.kind == ArgKind::Sizes) {
                if (n.sizes.empty()) failAt(d.opAt, std::string(op.name) + " needs at least one size: split(x, 1, ~2, 1)");
                n.args.emplace_back();
                continue;
            }
            if (spec.kind == ArgKind::Keys) {
                if (n.sizes.empty())
                    failAt(d.opAt, std::string(op.name) + " needs at least one key: " + op.name + "(scope.size.y, scope.origin.x)");
                n.args.emplace_back();
                continue;
            }
            if (!values[k] && !spec.fallback) failAt(d.opAt, std::string(op.name) + " needs argument '" + spec.name + "'");
            n.args.push_back(values[k] ? *values[k] : spec.fallback);
        }
    }

    void include(const PcgFile& f, const NodeDecl& d, const std::string& prefix, const Renames& rename, LocalNode& l) {
        const fs::path full = fs::path(f.path).parent_path() / d.file;
        std::error_code ec;
        const std::string canonical = fs::weakly_canonical(full, ec).string();
        for (std::size_t k = 0; k < stack_.size(); ++k)
            if (stack_[k] == canonical) {
                std::string chain;
                for (std::size_t j = k; j < stack_.size(); ++j) chain += fs::path(stack_[j]).filename().string() + " -> ";
                failAt(d.opAt, "include cycle: " + chain + d.file);
            }
        if (stack_.size() >= kMaxIncludeDepth) failAt(d.opAt, "includes nest deeper than 32 files");
        std::ifstream in;
        if (fs::is_regular_file(full, ec)) in.open(full, std::ios::binary);
        if (!in.is_open() || !in)
            failAt(d.opAt, "cannot open graph file '" + shortened(d.file) + "' (looked for " + shortened(full.string(), 200) + ")");
        std::ostringstream text;
        text << in.rdbuf();
        const std::string relative = full.lexically_normal().lexically_relative(mainDir_.lexically_normal()).generic_string();
        if (std::find(g_.files.begin(), g_.files.end(), relative) == g_.files.end()) g_.files.push_back(relative);
        files_.push_back(readPcg(text.str(), full.string()));
        const PcgFile& sub = files_.back();
        std::map<std::string, std::string> bound;
        for (const Arg& a : d.args) {
            if (a.name.empty()) failAt(a.where, "include arguments are named: include \"" + d.file + "\"(NAME: VALUE)");
            const bool known = std::any_of(sub.params.begin(), sub.params.end(), [&](const ParamDecl& p) { return p.name == a.name; }) ||
                               std::any_of(sub.attrs.begin(), sub.attrs.end(), [&](const AttrDecl& x) { return x.name == a.name; });
            if (!known) failAt(a.where, d.file + " has no param or attr '" + a.name + "'");
            if (bound.count(a.name)) failAt(a.where, "argument '" + a.name + "' is given twice");
            bound[a.name] = expressionText(a.value, rename);
        }
        stack_.push_back(canonical);
        const std::uint32_t outer = scope_;
        std::string shown = prefix + d.id;
        for (std::size_t k; (k = shown.find("__")) != std::string::npos;) shown.replace(k, 2, "/");
        g_.scopes.push_back({prefix + d.id, shown + " (" + d.file + ")", std::int32_t(outer), {}});
        instance(sub, prefix + d.id + "__", bound, &l);
        scope_ = outer;
        stack_.pop_back();
        for (auto& [name, node] : l.gateIn) g_.nodes[node].includeAt = d.where, g_.nodes[node].includeName = d.id;
    }

    [[noreturn]] void noPort(const PortRef& r, const LocalNode& l, bool output, const std::vector<std::string>& ports) {
        const std::string side = output ? "output" : "input";
        if (r.port.empty())
            failAt(r.where, "node '" + r.node + "' (" + l.what + ") has " + std::to_string(ports.size()) + " " + side +
                                " ports (" + joined(ports) + "): name one, " + r.node + ".PORT");
        failAt(r.where, "node '" + r.node + "' (" + l.what + ") has no " + side + " port '" + r.port + "' (its " + side +
                            "s: " + joined(ports) + ")");
    }

    std::pair<std::uint32_t, std::uint32_t> port(const PortRef& r, const Locals& local, bool output) {
        const auto it = local.find(r.node);
        if (it == local.end()) failAt(r.where, "unknown node '" + shortened(r.node) + "'");
        const LocalNode& l = it->second;
        if (l.include) {
            const auto& gates = output ? l.gateOut : l.gateIn;
            const auto& names = output ? l.outNames : l.inNames;
            if (r.port.empty() && names.size() == 1) return {gates.at(names[0]), 0};
            const auto g = gates.find(r.port);
            if (r.port.empty() || g == gates.end()) noPort(r, l, output, names);
            return {g->second, 0};
        }
        const FlatNode& n = g_.nodes[l.node];
        if (n.gate) {
            if (!r.port.empty()) failAt(r.where, "'" + r.node + "' is a gate, a port itself: write " + r.node + " without a port");
            if (gateInput_[l.node] != output)
                failAt(r.where, "'" + r.node + "' is an " + (output ? "output" : "input") + " gate: edges " +
                                    (output ? "end there (... -> " : "start there (") + r.node + (output ? ")" : " -> ...)"));
            return {l.node, 0};
        }
        const std::vector<FlatPort>& ports = output ? n.outputs : n.inputs;
        std::vector<std::string> names;
        for (const FlatPort& p : ports) names.push_back(p.name);
        if (r.port.empty() && ports.size() == 1) return {l.node, 0};
        for (std::size_t k = 0; k < ports.size(); ++k)
            if (!r.port.empty() && ports[k].name == r.port) return {l.node, std::uint32_t(k)};
        noPort(r, l, output, names);
    }
    std::pair<std::uint32_t, std::uint32_t> source(const PortRef& r, const Locals& local) { return port(r, local, true); }
    std::pair<std::uint32_t, std::uint32_t> destination(const PortRef& r, const Locals& local) { return port(r, local, false); }

    fs::path mainDir_;
    FlatGraph g_;
    std::deque<PcgFile> files_;
    std::vector<std::string> stack_;  ///< canonical paths of the files being read, the main file first
    std::vector<bool> gateInput_;     ///< per node: an input gate
    std::uint32_t scope_ = 0;         ///< the execution scope of the instance being read
};

}  // namespace graph_detail

using namespace graph_detail;

FlatGraph buildPcgGraph(const std::string& text, const std::string& path) {
    FlatGraph g = Builder(path).build(text, path);
    checkPcgGraph(g);
    return g;
}

}  // namespace shapevo::pcg
