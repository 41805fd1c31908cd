// readProduction: one production — its mother graph (match conditions), vectors, geometric
// ordering and daughter options (morphism, requirements, variables, attribute expressions), every
// id reference checked and every expression compiled against the names its place may see.
#include <map>

#include "base/input_error.hpp"
#include "graph/reader_context.hpp"

namespace shapevo::graph::reading {

namespace {

struct MotherIds {
    std::map<std::int64_t, int> vertices, edges;  // file id -> index
    std::map<std::int64_t, int> helpers;          // editor helper vertices (dropped)
};

/// The ids of a graph's vertex list, declared; helper vertices set aside.
void readVertexIds(ReaderContext& c, const YamlNode& graph, const std::string& what, std::map<std::int64_t, int>& ids,
                   std::map<std::int64_t, int>& helpers, std::vector<const YamlNode*>& nodes) {
    const YamlNode* vs = graph.find("vertices");
    if (!vs || vs->kind == YamlNode::Kind::Null) return;
    for (const YamlNode& v : c.sequence(*vs, what + " vertices").items) {
        std::string vwhat;
        const YamlNode& idNode = c.elementEntry(v, true, what, vwhat);
        if (isHelperVertex(v)) {
            helpers[idNode.integer] = 0;
            continue;
        }
        ids[idNode.integer] = int(nodes.size());
        nodes.push_back(&v);
    }
}

int endOf(ReaderContext& c, const YamlNode& edge, const char* key, const std::map<std::int64_t, int>& vertices,
          const std::map<std::int64_t, int>& helpers, const std::string& what) {
    const YamlNode* ref = edge.find(key);
    if (!ref || ref->kind == YamlNode::Kind::Null) return -1;
    const std::int64_t id = c.id(*ref, what + " " + key);
    if (helpers.count(id)) return -1;
    const auto it = vertices.find(id);
    if (it == vertices.end()) c.fail(*ref, what + ": " + key + " " + std::to_string(id) + " is not a vertex of this graph");
    return it->second;
}

Vec2 positionOf(ReaderContext& c, const YamlNode& attrs, const std::string& what) {
    return {c.number(c.required(attrs, "x", what), what + " x"), c.number(c.required(attrs, "y", what), what + " y")};
}

NameSlots conditionSlots(const std::vector<std::string>& globals) {
    NameSlots s;
    s.add("attr");
    s.add("attrs");
    for (const std::string& g : globals) s.add(g);
    return s;
}

std::vector<MatchCondition> readConditions(ReaderContext& c, const YamlNode* attrs, const NameSlots& slots, const std::string& what,
                                           bool* directed) {
    std::vector<MatchCondition> out;
    if (!attrs || attrs->kind == YamlNode::Kind::Null) return out;
    for (const auto& [k, value] : c.mapping(*attrs, what + " attr").entries) {
        const std::string key = c.keyText(k, what);
        if (key == "x" || key == "y") continue;
        if (key == ".directed" && directed) *directed = truthyScalar(value);
        if ((!key.empty() && key[0] == '.')) continue;
        const std::string place = what + ", condition on '" + shortened(key) + "'";
        out.push_back({c.names().intern(key), c.compile(value, slots, place), c.filePlace(value)});
    }
    return out;
}

void readMotherGraph(ReaderContext& c, const YamlNode& graph, const std::string& what, const std::vector<std::string>& globals,
                     Production& p, MotherIds& ids) {
    c.mapping(graph, what);
    c.onlyKeys(graph, {"id", "vertices", "edges"}, what);
    std::vector<const YamlNode*> vertexNodes;
    readVertexIds(c, graph, what, ids.vertices, ids.helpers, vertexNodes);
    const NameSlots slots = conditionSlots(globals);
    for (const YamlNode* v : vertexNodes) {
        const std::string vwhat = what + ", vertex " + idText(*v->find("id"));
        const YamlNode& attrs = c.mapping(c.required(*v, "attr", vwhat), vwhat + " attr");
        MotherVertex m;
        m.position = positionOf(c, attrs, vwhat);
        m.conditions = readConditions(c, &attrs, slots, vwhat, nullptr);
        m.place = c.filePlace(*v, v->find("id")->integer);
        p.motherVertices.push_back(std::move(m));
    }
    if (const YamlNode* es = graph.find("edges"); es && es->kind != YamlNode::Kind::Null) {
        for (const YamlNode& e : c.sequence(*es, what + " edges").items) {
            std::string ewhat;
            const YamlNode& idNode = c.elementEntry(e, false, what, ewhat);
            MotherEdge m;
            m.vertex1 = endOf(c, e, "vertex1", ids.vertices, ids.helpers, ewhat);
            m.vertex2 = endOf(c, e, "vertex2", ids.vertices, ids.helpers, ewhat);
            m.conditions = readConditions(c, e.find("attr"), slots, ewhat, &m.directed);
            m.place = c.filePlace(e, idNode.integer);
            ids.edges[idNode.integer] = int(p.motherEdges.size());
            p.motherEdges.push_back(std::move(m));
        }
    }
}

/// A mother element named by id: {isVertex, index}.
std::pair<bool, int> motherElement(ReaderContext& c, const YamlNode& ref, const MotherIds& ids, const std::string& what) {
    const std::int64_t id = c.id(ref, what);
    if (const auto it = ids.vertices.find(id); it != ids.vertices.end()) return {true, it->second};
    if (const auto it = ids.edges.find(id); it != ids.edges.end()) return {false, it->second};
    c.fail(ref, what + ": " + std::to_string(id) + " is not a vertex or edge of the production's mother graph");
}

}  // namespace

Production readProduction(ReaderContext& c, const std::string& name, const YamlNode& node, const std::vector<std::string>& globals) {
    const std::string what = "production '" + shortened(name) + "'";
    c.mapping(node, what);
    c.onlyKeys(node, {"id", "priority", "conditions", "vectors", "mother_graph", "mappings"}, what);
    Production p;
    p.name = name;
    p.place = c.filePlace(node);
    c.declareId(c.required(node, "id", what), what);
    if (const YamlNode* pr = node.find("priority"); pr && pr->kind != YamlNode::Kind::Null) {
        const std::int64_t priority = c.integer(*pr, what + " priority");
        if (priority < -1'000'000 || priority > 1'000'000) c.fail(*pr, what + ": priority must be within ±1000000");
        p.priority = int(priority);
    }
    const YamlNode& mother = c.required(node, "mother_graph", what);
    c.mapping(mother, what + " mother graph");
    const YamlNode& motherId = c.required(mother, "id", what + " mother graph");
    c.declareId(motherId, what + " mother graph");
    MotherIds ids;
    c.countScope(globals.size() + 2, node, what);
    readMotherGraph(c, mother, what + " mother graph", globals, p, ids);
    if (const YamlNode* cond = node.find("conditions"); cond && cond->kind != YamlNode::Kind::Null) {
        c.mapping(*cond, what + " conditions");  // only .geometric_ordering is read (the original reads no other key)
        if (const YamlNode* go = cond->find(".geometric_ordering")) {
            NameSlots slots;
            for (const std::string& g : globals) slots.add(g);
            p.geometricOrdering = c.compile(*go, slots, what + ", .geometric_ordering");
        }
    }
    if (const YamlNode* vs = node.find("vectors"); vs && vs->kind != YamlNode::Kind::Null) {
        if (c.mapping(*vs, what + " vectors").entries.size() > kMaxOptionNames)
            c.fail(*vs, what + ": more than " + std::to_string(kMaxOptionNames) + " vectors");
        for (const auto& [k, ref] : vs->entries) {
            Production::Vector v;
            v.name = c.keyText(k, what + " vectors");
            const std::string vwhat = what + ", vector '" + shortened(v.name) + "'";
            auto vertexIndex = [&](const YamlNode& r) {
                const auto [isVertex, index] = motherElement(c, r, ids, vwhat);
                if (!isVertex) c.fail(r, vwhat + ": " + idText(r) + " is an edge; a vector names mother vertices");
                return index;
            };
            if (ref.kind == YamlNode::Kind::Sequence) {
                if (ref.items.size() != 2) c.fail(ref, vwhat + ": a direction vector is [from, to], two mother vertex ids");
                v.from = vertexIndex(ref.items[0]);
                v.to = vertexIndex(ref.items[1]);
            } else {
                v.to = vertexIndex(ref);
            }
            for (const Production::Vector& other : p.vectors)
                if (other.name == v.name) c.fail(k, vwhat + " is given twice");
            p.vectors.push_back(std::move(v));
        }
    }
    const YamlNode& mappings = c.sequence(c.required(node, "mappings", what), what + " mappings");
    if (mappings.items.empty()) c.fail(mappings, what + " has no option in 'mappings' (one daughter graph at least)");
    for (const YamlNode& option : mappings.items)
        p.options.push_back(readOption(c, option, what, p, motherId.integer, ids.vertices, ids.edges, globals));
    return p;
}

}  // namespace shapevo::graph::reading
