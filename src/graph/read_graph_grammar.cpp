// readGraphGrammar: the top level of a graph grammar file — host graphs, global variables,
// options.max_derivations, the SVG preamble — and the productions through read_production.cpp.
#include "graph/read_graph_grammar.hpp"

#include <filesystem>

#include <fstream>
#include <set>

#include "base/input_error.hpp"
#include "graph/reader_context.hpp"

namespace shapevo::graph {

namespace reading {

HostGraph readHostGraph(ReaderContext& c, const std::string& name, const YamlNode& node, const GraphGrammar::Keys& keys) {
    const std::string what = "host graph '" + shortened(name) + "'";
    c.mapping(node, what);
    c.onlyKeys(node, {"id", "vertices", "edges"}, what);
    c.declareId(c.required(node, "id", what), what);
    HostGraph g;
    std::map<std::int64_t, ElementId> vertexIds;
    std::set<std::int64_t> helpers;
    if (const YamlNode* vs = node.find("vertices"); vs && vs->kind != YamlNode::Kind::Null) {
        for (const YamlNode& v : c.sequence(*vs, what + " vertices").items) {
            std::string vwhat;
            const YamlNode& idNode = c.elementEntry(v, true, what, vwhat);
            const YamlNode& attrs = c.mapping(c.required(v, "attr", vwhat), vwhat + " attr");
            if (isHelperVertex(v)) {
                helpers.insert(idNode.integer);
                continue;
            }
            Vec2 position{c.number(c.required(attrs, "x", vwhat), vwhat + " x"), c.number(c.required(attrs, "y", vwhat), vwhat + " y")};
            AttrMap map;
            std::int64_t generation = 0;
            for (const auto& [k, value] : attrs.entries) {
                const std::string key = c.keyText(k, vwhat);
                if (key == "x" || key == "y") continue;
                const AttrKey ak = c.names().intern(key);
                map.set(ak, c.plainValue(value, vwhat + " " + key));
                if (ak == keys.generation) generation = c.integer(value, vwhat + " .generation");
            }
            vertexIds[idNode.integer] = g.addVertex(position, std::move(map), generation);
        }
    }
    if (const YamlNode* es = node.find("edges"); es && es->kind != YamlNode::Kind::Null) {
        for (const YamlNode& e : c.sequence(*es, what + " edges").items) {
            std::string ewhat;
            c.elementEntry(e, false, what, ewhat);
            ElementId ends[2] = {kNoVertex, kNoVertex};
            for (int end = 0; end < 2; ++end) {
                const char* key = end == 0 ? "vertex1" : "vertex2";
                const YamlNode* ref = e.find(key);
                if (!ref || ref->kind == YamlNode::Kind::Null) continue;
                const std::int64_t id = c.id(*ref, ewhat + " " + key);
                if (helpers.count(id)) continue;  // an editor helper: the end dangles
                const auto it = vertexIds.find(id);
                if (it == vertexIds.end()) c.fail(*ref, ewhat + ": " + key + " " + std::to_string(id) + " is not a vertex of this graph");
                ends[end] = it->second;
            }
            AttrMap map;
            std::int64_t generation = 0;
            if (const YamlNode* attrs = e.find("attr"); attrs && attrs->kind != YamlNode::Kind::Null) {
                for (const auto& [k, value] : c.mapping(*attrs, ewhat + " attr").entries) {
                    const std::string key = c.keyText(k, ewhat);
                    const AttrKey ak = c.names().intern(key);
                    map.set(ak, c.plainValue(value, ewhat + " " + key));
                    if (ak == keys.generation) generation = c.integer(value, ewhat + " .generation");
                }
            }
            g.addEdge(ends[0], ends[1], std::move(map), generation);
        }
    }
    return g;
}

namespace {

void readLimits(ReaderContext& c, const YamlNode& options, GraphGrammar& g) {
    c.mapping(options, "options");
    c.onlyKeys(options, {"max_derivations"}, "options");
    const YamlNode* md = options.find("max_derivations");
    if (!md || md->kind == YamlNode::Kind::Null) return;
    for (const auto& [k, v] : c.mapping(*md, "options.max_derivations").entries) {
        const std::int64_t n = c.integer(v, "options.max_derivations." + shortened(k.text));
        if (n < 0) c.fail(v, "options.max_derivations." + shortened(k.text) + " must be 0 or more");
        if (k.isScalar() && k.text == "all") {
            g.globalLimit = n;
            continue;
        }
        const std::int64_t priority = c.integer(k, "options.max_derivations: a key (a priority or 'all')");
        if (priority < -1'000'000 || priority > 1'000'000) c.fail(k, "options.max_derivations: a priority must be within ±1000000");
        g.priorityLimits.emplace_back(int(priority), n);
    }
}

void readPreamble(ReaderContext& c, const YamlNode& svg, GraphGrammar& g) {
    c.mapping(svg, "svg");
    c.onlyKeys(svg, {"preamble"}, "svg");
    const YamlNode* pre = svg.find("preamble");
    if (!pre || pre->kind == YamlNode::Kind::Null) return;
    c.mapping(*pre, "svg.preamble");
    c.onlyKeys(*pre, {"filter"}, "svg.preamble");
    const YamlNode* filters = pre->find("filter");
    if (!filters || filters->kind == YamlNode::Kind::Null) return;
    for (const auto& [idNode, body] : c.mapping(*filters, "svg.preamble.filter").entries) {
        SvgFilter f;
        f.id = c.keyText(idNode, "svg.preamble.filter");
        const std::string what = "svg filter '" + shortened(f.id) + "'";
        for (const auto& [tag, kwargs] : c.mapping(body, what).entries) {
            SvgFilter::Primitive p;
            p.tag = c.keyText(tag, what);
            if (kwargs.kind != YamlNode::Kind::Null)
                for (const auto& [name, value] : c.mapping(kwargs, what + " " + p.tag).entries)
                    p.attributes.emplace_back(c.keyText(name, what), c.expressionText(value, what + " " + shortened(name.text)));
            f.primitives.push_back(std::move(p));
        }
        g.filters.push_back(std::move(f));
    }
}

}  // namespace

}  // namespace reading

namespace {

GraphGrammar grammarOf(const YamlNode& root, const std::string& path, std::string_view source) {
    using namespace reading;
    GraphGrammar g;
    g.source = std::string(source);
    g.path = path;
    g.keys.generation = g.names.intern(".generation");
    g.keys.directed = g.names.intern(".directed");
    g.keys.svgTag = g.names.intern(".svg_tag");
    g.keys.helperNode = g.names.intern(".helper_node");
    ReaderContext c(path, g.names, source);
    if (root.kind == YamlNode::Kind::Null && root.text.empty()) c.fail(root, "the file is empty (a graph grammar file is a mapping with host_graphs and productions)");
    if (root.kind != YamlNode::Kind::Mapping) c.fail(root, "a graph grammar file must be a mapping with host_graphs and productions, not " + root.describe());
    c.onlyKeys(root, {"host_graphs", "productions", "result_graphs", "global_vars", "options", "svg", "extra"}, "the file");
    const YamlNode& hosts = c.mapping(c.required(root, "host_graphs", "the file"), "host_graphs");
    const YamlNode& productions = c.mapping(c.required(root, "productions", "the file"), "productions");
    c.required(root, "result_graphs", "the file");
    if (hosts.entries.empty()) c.fail(hosts, "host_graphs is empty: a derivation starts from a host graph");
    for (const auto& [name, graph] : hosts.entries) {
        const std::string n = c.keyText(name, "host_graphs");
        g.hosts.push_back({n, readHostGraph(c, n, graph, g.keys)});
    }
    std::vector<std::string> globalNames;
    if (const YamlNode* globals = root.find("global_vars"); globals && globals->kind != YamlNode::Kind::Null) {
        const NameSlots none;
        if (globals->entries.size() > kMaxGlobalVariables)
            c.fail(*globals, "global_vars: more than " + std::to_string(kMaxGlobalVariables) + " global variables");
        for (const auto& [name, expr] : c.mapping(*globals, "global_vars").entries) {
            const std::string n = c.keyText(name, "global_vars");
            g.globals.push_back({n, c.compile(expr, none, "global variable '" + shortened(n) + "'"), c.filePlace(expr)});
            globalNames.push_back(n);
        }
    }
    if (const YamlNode* options = root.find("options"); options && options->kind != YamlNode::Kind::Null) readLimits(c, *options, g);
    if (const YamlNode* svg = root.find("svg"); svg && svg->kind != YamlNode::Kind::Null) readPreamble(c, *svg, g);
    for (const auto& [name, body] : productions.entries)
        g.productions.push_back(readProduction(c, c.keyText(name, "productions"), body, globalNames));
    return g;
}

}  // namespace

GraphGrammar parseGraphGrammar(std::string_view text, const std::string& path) { return grammarOf(parseYaml(text, path), path, text); }

GraphGrammar readGraphGrammar(const std::string& path) {
    const YamlNode root = readYamlFile(path);  // the size limit, read errors
    // The text again, for expression errors' columns; none if it grew past the limit meanwhile.
    std::string text;
    std::ifstream in(path, std::ios::binary);
    char block[1 << 16];
    while (in.read(block, sizeof block) || in.gcount() > 0) {
        text.append(block, std::size_t(in.gcount()));
        if (text.size() > YamlLimits{}.maxBytes) {
            text.clear();
            break;
        }
    }
    return grammarOf(root, path, text);
}

bool isGraphGrammarPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return ext == ".yml" || ext == ".yaml";
}

}  // namespace shapevo::graph
