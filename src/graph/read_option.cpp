// readOption: one daughter option of a production — its daughter graph, the partial morphism
// from the mother graph, attr_requirements, var_calc_instructions and weight — and the slot
// layout its expressions are compiled against (graph-grammar README, section 2.5).
#include <functional>
#include <map>
#include <set>
#include <utility>

#include "base/input_error.hpp"
#include "graph/reader_context.hpp"

namespace shapevo::graph::reading {

namespace {

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

/// A NameSlots with the same indices where only the names in [from, to) ∪ `also` are visible:
/// an expression sees only its place's names, but evaluates in the option's one frame.
NameSlots visibleOnly(const NameSlots& all, const std::vector<std::pair<std::size_t, std::size_t>>& ranges) {
    NameSlots s = all;
    for (std::size_t i = 0; i < s.names.size(); ++i) {
        bool visible = false;
        for (const auto& [from, to] : ranges) visible = visible || (i >= from && i < to);
        if (!visible) s.names[i].clear();  // "" matches no identifier
    }
    return s;
}

struct DaughterIds {
    std::map<std::int64_t, int> vertices, edges, helpers;
};

std::vector<DaughterAttr> readDaughterAttrs(ReaderContext& c, const YamlNode* attrs, const NameSlots& slots, const std::string& what,
                                            DaughterVertex* vertex) {
    std::vector<DaughterAttr> out;
    if (!attrs || attrs->kind == YamlNode::Kind::Null) return out;
    for (const auto& [k, value] : c.mapping(*attrs, what + " attr").entries) {
        const std::string key = c.keyText(k, what);
        const std::string place = what + ", attribute '" + shortened(key) + "'";
        if (vertex && (key == "x" || key == "y")) continue;
        if (vertex && (key == "new_x" || key == "new_y" || key == ".new_pos")) {
            CompiledExpression e = c.compile(value, slots, place);
            (key == "new_x" ? vertex->newX : key == "new_y" ? vertex->newY : vertex->newPos) = std::move(e);
            continue;
        }
        DaughterAttr a;
        a.key = c.names().intern(key);
        a.place = c.filePlace(value);
        const bool evaluated = !startsWith(key, ".") || startsWith(key, ".svg_") || startsWith(key, ".svgx_");
        if (evaluated) {
            a.expression = c.compile(value, slots, place);
        } else {
            a.verbatim = true;
            a.value = c.plainValue(value, place);
        }
        out.push_back(std::move(a));
    }
    return out;
}

/// The daughter graph's element ids (declared; helper vertices set aside) and nodes, in file order.
void readDaughterIds(ReaderContext& c, const YamlNode& node, const std::string& what, DaughterIds& ids,
                     std::vector<const YamlNode*>& vertexNodes, std::vector<const YamlNode*>& edgeNodes) {
    const YamlNode* daughter = node.find("daughter_graph");
    const std::string dwhat = what + " daughter graph";
    if (daughter && daughter->kind != YamlNode::Kind::Null) {
        c.mapping(*daughter, dwhat);
        c.onlyKeys(*daughter, {"id", "vertices", "edges"}, dwhat);
        c.declareId(c.required(*daughter, "id", dwhat), dwhat);
        if (const YamlNode* vs = daughter->find("vertices"); vs && vs->kind != YamlNode::Kind::Null)
            for (const YamlNode& v : c.sequence(*vs, dwhat + " vertices").items) {
                std::string vwhat;
                const YamlNode& vid = c.elementEntry(v, true, dwhat, vwhat);
                if (isHelperVertex(v)) {
                    ids.helpers[vid.integer] = 0;
                    continue;
                }
                ids.vertices[vid.integer] = int(vertexNodes.size());
                vertexNodes.push_back(&v);
            }
        if (const YamlNode* es = daughter->find("edges"); es && es->kind != YamlNode::Kind::Null)
            for (const YamlNode& e : c.sequence(*es, dwhat + " edges").items) {
                std::string ewhat;
                const YamlNode& eid = c.elementEntry(e, false, dwhat, ewhat);
                ids.edges[eid.integer] = int(edgeNodes.size());
                edgeNodes.push_back(&e);
            }
    }
}

/// The morphism: mother element -> daughter element of the same kind, one to one.
void readMorphism(ReaderContext& c, const YamlNode& node, const std::string& what, const DaughterIds& ids,
                  const std::map<std::int64_t, int>& motherVertexIds, const std::map<std::int64_t, int>& motherEdgeIds,
                  ProductionOption& o) {
    if (const YamlNode* mapping = node.find("mapping"); mapping && mapping->kind != YamlNode::Kind::Null) {
        c.mapping(*mapping, what + " mapping");
        c.onlyKeys(*mapping, {"id", "dict"}, what + " mapping");
        if (const YamlNode* mid = mapping->find("id")) c.declareId(*mid, what + " mapping");
        if (const YamlNode* dict = mapping->find("dict"); dict && dict->kind != YamlNode::Kind::Null)
            for (const auto& [from, to] : c.mapping(*dict, what + " mapping dict").entries) {
                const std::int64_t m = c.id(from, what + " mapping: a mother element id");
                const std::int64_t d = c.id(to, what + " mapping: a daughter element id");
                const auto mv = motherVertexIds.find(m), me = motherEdgeIds.find(m);
                if (mv == motherVertexIds.end() && me == motherEdgeIds.end())
                    c.fail(from, what + " mapping: " + idText(from) + " is not a vertex or edge of the mother graph");
                const bool vertex = mv != motherVertexIds.end();
                const auto& targets = vertex ? ids.vertices : ids.edges;
                const auto t = targets.find(d);
                if (t == targets.end())
                    c.fail(to, what + " mapping: " + idText(to) + " is not a " + (vertex ? "vertex" : "edge") + " of the daughter graph (the mother " +
                                   (vertex ? "vertex " : "edge ") + idText(from) + " must map to one)");
                int& mother = vertex ? o.vertices[std::size_t(t->second)].mother : o.edges[std::size_t(t->second)].mother;
                if (mother >= 0) c.fail(to, what + " mapping: two mother elements map to daughter element " + idText(to) + " (merging is not supported)");
                mother = vertex ? mv->second : me->second;
            }
    }

}

/// An option's weight, `generation: oldest` and its mother graph reference.
void readOptionHeader(ReaderContext& c, const YamlNode& node, const std::string& what, std::int64_t motherGraphId,
                      ProductionOption& o) {
    if (const YamlNode* mg = node.find("mother_graph"); mg && mg->kind != YamlNode::Kind::Null)
        if (c.id(*mg, what + " mother_graph") != motherGraphId)
            c.fail(*mg, what + ": mother_graph " + idText(*mg) + " is not this production's mother graph (" + std::to_string(motherGraphId) + ")");
    if (const YamlNode* w = node.find("weight"); w && w->kind != YamlNode::Kind::Null) {
        o.weight = c.integer(*w, what + " weight");
        if (o.weight < 0 || o.weight > (std::int64_t(1) << 40)) c.fail(*w, what + ": weight must be 0 to 2^40");
    }
    if (const YamlNode* cond = node.find("conditions"); cond && cond->kind != YamlNode::Kind::Null) {
        c.mapping(*cond, what + " conditions");  // only `generation: oldest` has an effect, as in the original
        if (const YamlNode* g = cond->find("generation"); g && g->isScalar() && g->text == "oldest") o.oldest = true;
    }

}

/// Each daughter element's own attr_requirements, checked, by the element's id.
std::map<std::int64_t, std::vector<Requirement>> readOwnRequirements(
    ReaderContext& c, const std::vector<std::pair<const YamlNode*, const YamlNode*>>& ownRequirements, const std::string& what,
    const DaughterIds& ids, const std::map<std::int64_t, int>& motherVertexIds, const std::map<std::int64_t, int>& motherEdgeIds,
    const std::set<std::string>& taken) {
    std::map<std::int64_t, std::vector<Requirement>> own;
    for (const auto& [target, names] : ownRequirements) {
        const std::int64_t d = c.id(*target, what + " attr_requirements: a daughter element id");
        if (!ids.vertices.count(d) && !ids.edges.count(d))
            c.fail(*target, what + " attr_requirements: " + idText(*target) + " is not a vertex or edge of the daughter graph");
        for (const auto& [name, ref] : c.mapping(*names, what + " attr_requirements " + idText(*target)).entries) {
            const std::int64_t m = c.id(ref, what + " attr_requirements");
            Requirement r{c.keyText(name, what), motherVertexIds.count(m) > 0, 0};
            if (r.motherIsVertex) r.motherIndex = motherVertexIds.at(m);
            else if (motherEdgeIds.count(m)) r.motherIndex = motherEdgeIds.at(m);
            else c.fail(ref, what + " attr_requirements: " + idText(ref) + " is not a vertex or edge of the mother graph");
            if (taken.count(r.name))
                c.fail(name, what + ": the requirement '" + shortened(r.name) +
                                 "' has the name of a vector, a requirement for all or a variable of this option");
            std::vector<Requirement>& list = own[d];
            if (list.size() >= kMaxOptionNames)
                c.fail(name, what + " attr_requirements: more than " + std::to_string(kMaxOptionNames) + " requirements for one element");
            list.push_back(std::move(r));
        }
    }
    return own;
}

/// A daughter edge's ends as daughter vertex indices (-1: none, or an editor helper).
void readDaughterEdgeEnds(ReaderContext& c, const YamlNode& e, const std::string& ewhat, const DaughterIds& ids, DaughterEdge& d) {
    for (int end = 0; end < 2; ++end) {
        const char* key = end == 0 ? "vertex1" : "vertex2";
        const YamlNode* ref = e.find(key);
        int& slot = end == 0 ? d.vertex1 : d.vertex2;
        if (!ref || ref->kind == YamlNode::Kind::Null) continue;
        const std::int64_t vid = c.id(*ref, ewhat + " " + key);
        if (ids.helpers.count(vid)) continue;
        const auto it = ids.vertices.find(vid);
        if (it == ids.vertices.end()) c.fail(*ref, ewhat + ": " + key + " " + ref->text + " is not a vertex of the daughter graph");
        slot = it->second;
    }
}

}  // namespace

ProductionOption readOption(ReaderContext& c, const YamlNode& node, const std::string& production, const Production& p,
                            std::int64_t motherGraphId, const std::map<std::int64_t, int>& motherVertexIds,
                            const std::map<std::int64_t, int>& motherEdgeIds, const std::vector<std::string>& globals) {
    c.mapping(node, production + " option");
    c.onlyKeys(node, {"id", "mother_graph", "daughter_graph", "mapping", "weight", "attr_requirements", "conditions", "var_calc_instructions"},
               production + " option");
    const YamlNode& idNode = c.required(node, "id", production + " option");
    const std::string what = production + ", option " + idText(idNode);
    c.declareId(idNode, what);
    ProductionOption o;
    o.place = c.filePlace(node, idNode.integer);
    readOptionHeader(c, node, what, motherGraphId, o);

    // The daughter graph's elements (ids first: the morphism and requirements refer to them).
    DaughterIds ids;
    std::vector<const YamlNode*> vertexNodes, edgeNodes;
    readDaughterIds(c, node, what, ids, vertexNodes, edgeNodes);
    const std::string dwhat = what + " daughter graph";
    o.vertices.resize(vertexNodes.size());
    o.edges.resize(edgeNodes.size());

    readMorphism(c, node, what, ids, motherVertexIds, motherEdgeIds, o);

    // The option's one frame: self_, old, vectors, `all` requirements, application variables, run
    // variables, globals; then each element's own requirements.
    NameSlots& s = o.slots;
    std::set<std::string> taken;
    auto add = [&](const std::string& name, const YamlNode& at, const std::string& kind) {
        if (s.names.size() >= kMaxOptionNames + 2)
            c.fail(at, what + ": more than " + std::to_string(kMaxOptionNames) + " vectors, requirements for all and variables");
        if (!taken.insert(name).second) c.fail(at, what + ": the name '" + shortened(name) + "' (" + kind + ") is already used by another name of this option");
        s.add(name);
    };
    s.add("self_");
    s.add("old");
    taken = {"self_", "old"};
    for (const Production::Vector& v : p.vectors) {
        if (!taken.insert(v.name).second) c.fail(node, what + ": vector '" + shortened(v.name) + "' uses a reserved name");
        s.add(v.name);
    }
    std::vector<std::pair<const YamlNode*, const YamlNode*>> ownRequirements;  // (daughter id node, names)
    if (const YamlNode* req = node.find("attr_requirements"); req && req->kind != YamlNode::Kind::Null)
        for (const auto& [target, names] : c.mapping(*req, what + " attr_requirements").entries) {
            if (target.isScalar() && target.text == "all") {
                for (const auto& [name, ref] : c.mapping(names, what + " attr_requirements all").entries) {
                    const std::string n = c.keyText(name, what);
                    const std::int64_t m = c.id(ref, what + " attr_requirements");
                    Requirement r{n, motherVertexIds.count(m) > 0, 0};
                    if (r.motherIsVertex) r.motherIndex = motherVertexIds.at(m);
                    else if (motherEdgeIds.count(m)) r.motherIndex = motherEdgeIds.at(m);
                    else c.fail(ref, what + " attr_requirements: " + idText(ref) + " is not a vertex or edge of the mother graph");
                    add(n, name, "a requirement for all");
                    o.requirementsForAll.push_back(std::move(r));
                }
            } else {
                ownRequirements.emplace_back(&target, &names);
            }
        }
    const std::size_t allEnd = s.names.size();
    // var_calc_instructions: [name, expression, run | application]
    std::vector<std::pair<const YamlNode*, const YamlNode*>> variableNodes;
    if (const YamlNode* vars = node.find("var_calc_instructions"); vars && vars->kind != YamlNode::Kind::Null)
        for (const YamlNode& v : c.sequence(*vars, what + " var_calc_instructions").items) {
            if (v.kind != YamlNode::Kind::Sequence || v.items.size() != 3)
                c.fail(v, what + " var_calc_instructions: each is [name, expression, run | application]");
            for (const YamlNode& item : {std::cref(v.items[0]), std::cref(v.items[2])})
                if (!item.isScalar()) c.fail(item, what + " var_calc_instructions: a name and a kind are single words, not " + item.describe());
            const std::string kind = v.items[2].text;
            if (kind != "run" && kind != "application")
                c.fail(v.items[2], what + " var_calc_instructions: '" + shortened(kind) + "' is neither run nor application");
            OptionVariable var;
            var.name = c.keyText(v.items[0], what);
            var.perRun = kind == "run";
            var.place = c.filePlace(v);
            o.variables.push_back(std::move(var));
            variableNodes.emplace_back(&v.items[0], &v.items[1]);
        }
    const std::size_t appBegin = s.names.size();
    for (std::size_t i = 0; i < o.variables.size(); ++i)
        if (!o.variables[i].perRun) add(o.variables[i].name, *variableNodes[i].first, "a per-application variable");
    const std::size_t runBegin = s.names.size();
    for (std::size_t i = 0; i < o.variables.size(); ++i)
        if (o.variables[i].perRun) add(o.variables[i].name, *variableNodes[i].first, "a per-run variable");
    const std::size_t globalsBegin = s.names.size();
    for (const std::string& g : globals) {
        if (taken.count(g)) continue;  // an option's own name hides a global of the same name
        s.add(g);
    }
    o.sharedSlots = s.names.size();
    c.countScope(o.sharedSlots, node, what);
    // Variables: application ones see the vectors, the `all` requirements and earlier application
    // variables; run ones see the globals and earlier run variables.
    // One layout per kind, each variable's name made visible once it is compiled (no copy per
    // variable: a file of many variables reads in linear time).
    NameSlots runVisible = visibleOnly(s, {{globalsBegin, o.sharedSlots}}), appVisible = visibleOnly(s, {{2, allEnd}});
    std::size_t appSeen = appBegin, runSeen = runBegin;
    for (std::size_t i = 0; i < o.variables.size(); ++i) {
        OptionVariable& var = o.variables[i];
        NameSlots& visible = var.perRun ? runVisible : appVisible;
        var.expression = c.compile(*variableNodes[i].second, visible, what + ", variable '" + shortened(var.name) + "'");
        std::size_t& seen = var.perRun ? runSeen : appSeen;
        visible.names[seen] = s.names[seen];
        ++seen;
    }

    // Daughter elements: own requirements after the shared slots, then the attribute expressions.
    const std::map<std::int64_t, std::vector<Requirement>> own =
        readOwnRequirements(c, ownRequirements, what, ids, motherVertexIds, motherEdgeIds, taken);
    // An element's layout: the shared slots, then its own requirements, which hide a global of
    // the same name (NameSlots::find takes the first). One working layout, restored after each
    // element: no copy per element.
    NameSlots element = s;
    element.names.resize(o.sharedSlots);
    std::vector<std::pair<std::size_t, std::string>> hidden;
    auto slotsFor = [&](std::int64_t id, std::vector<Requirement>& requirements) -> const NameSlots& {
        for (auto& [i, name] : hidden) element.names[i] = std::move(name);
        hidden.clear();
        element.names.resize(o.sharedSlots);
        if (const auto it = own.find(id); it != own.end()) {
            requirements = it->second;
            for (const Requirement& r : requirements) {
                const int global = element.find(r.name);
                if (global >= 0) hidden.emplace_back(std::size_t(global), std::exchange(element.names[std::size_t(global)], std::string()));
                element.add(r.name);
            }
        }
        return element;
    };
    for (std::size_t index = 0; index < vertexNodes.size(); ++index) {
        const YamlNode& v = *vertexNodes[index];
        const std::int64_t id = v.find("id")->integer;
        const std::string vwhat = dwhat + ", vertex " + std::to_string(id);
        DaughterVertex& d = o.vertices[index];
        const YamlNode& attrs = c.mapping(c.required(v, "attr", vwhat), vwhat + " attr");
        d.position = {c.number(c.required(attrs, "x", vwhat), vwhat + " x"), c.number(c.required(attrs, "y", vwhat), vwhat + " y")};
        d.attrs = readDaughterAttrs(c, &attrs, slotsFor(id, d.requirements), vwhat, &d);
        d.place = c.filePlace(v, id);
    }
    for (std::size_t index = 0; index < edgeNodes.size(); ++index) {
        const YamlNode& e = *edgeNodes[index];
        const std::int64_t id = e.find("id")->integer;
        const std::string ewhat = dwhat + ", edge " + std::to_string(id);
        DaughterEdge& d = o.edges[index];
        readDaughterEdgeEnds(c, e, ewhat, ids, d);
        d.attrs = readDaughterAttrs(c, e.find("attr"), slotsFor(id, d.requirements), ewhat, nullptr);
        d.place = c.filePlace(e, id);
    }
    return o;
}

}  // namespace shapevo::graph::reading
