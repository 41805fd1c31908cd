// Rewriter: the single push-out, positions and daughter expressions of one step (rewrite.hpp).
#include "graph/rewrite.hpp"

#include <algorithm>

#include "base/input_error.hpp"
#include "graph/auto_position.hpp"
#include "graph/lineage_key.hpp"

namespace shapevo::graph {

namespace {

bool readsSlot(const CompiledExpression& e, int slot) {
    const std::vector<int>& read = e.slotsRead();
    return std::binary_search(read.begin(), read.end(), slot);
}

std::string placeText(const FilePlace& p) { return std::to_string(p.line) + ":" + std::to_string(p.column); }

}  // namespace

Rewriter::Rewriter(const GraphGrammar& grammar, const std::vector<Value>& globals, DrawSource& draws) : grammar_(grammar), draws_(draws) {
    frames_.resize(grammar.productions.size());
    for (std::size_t p = 0; p < grammar.productions.size(); ++p) {
        const Production& production = grammar.productions[p];
        for (const ProductionOption& o : production.options) {
            OptionFrame f;
            std::size_t ownMax = 0;
            for (const DaughterVertex& d : o.vertices) ownMax = std::max(ownMax, d.requirements.size());
            for (const DaughterEdge& d : o.edges) ownMax = std::max(ownMax, d.requirements.size());
            f.slots.resize(o.sharedSlots + ownMax);
            for (std::size_t i = 0; i < production.vectors.size(); ++i) f.vectorSlots.push_back(int(2 + i));
            for (std::size_t i = 0; i < o.requirementsForAll.size(); ++i) f.allSlots.push_back(int(2 + production.vectors.size() + i));
            for (const OptionVariable& v : o.variables) f.variableSlots.push_back(o.slots.find(v.name));
            const std::size_t globalsBegin = 2 + production.vectors.size() + o.requirementsForAll.size() + o.variables.size();
            for (std::size_t g = 0; g < grammar.globals.size(); ++g) {
                const int slot = o.slots.find(grammar.globals[g].name);
                if (slot >= int(globalsBegin)) f.slots[std::size_t(slot)] = globals[g];
            }
            f.runValues.resize(o.variables.size());
            for (std::size_t i = 0; i < o.variables.size(); ++i) {
                if (!o.variables[i].perRun) continue;
                f.runValues[i] = evaluate(o.variables[i].expression, f.slots, production, o, o.variables[i].place,
                                          Where{"variable", 0, &o.variables[i].name});
                f.slots[std::size_t(f.variableSlots[i])] = f.runValues[i];
            }
            auto scan = [&](const std::vector<DaughterAttr>& attrs) {
                for (const DaughterAttr& a : attrs) f.readsOld = f.readsOld || (!a.verbatim && readsSlot(a.expression, 1));
            };
            for (const DaughterVertex& d : o.vertices) {
                scan(d.attrs);
                for (const auto* e : {&d.newX, &d.newY, &d.newPos})
                    if (*e) f.readsOld = f.readsOld || readsSlot(**e, 1);
            }
            for (const DaughterEdge& d : o.edges) scan(d.attrs);
            frames_[p].push_back(std::move(f));
        }
    }
}

Value Rewriter::evaluate(const CompiledExpression& e, std::vector<Value>& slots, const Production& p, const ProductionOption& o,
                         const FilePlace& place, const Where& where) {
    const EvaluationFrame frame{slots.data(), slots.size(), &grammar_.names, &draws_};
    try {
        return e.evaluate(frame);
    } catch (const EvaluationError& error) {
        std::string what = where.kind;
        if (where.id) what += " " + std::to_string(where.id);
        if (where.name) what += std::string(", ") + where.nameKind + " '" + shortened(*where.name) + "'";
        throw InputError(grammar_.path, placeText(place),
                         "production '" + shortened(p.name) + "', option " + std::to_string(o.place.id) + ", " + what + ": " + error.what());
    }
}

void Rewriter::apply(HostGraph& graph, std::size_t production, std::size_t option, const ElementId* vertexImages,
                     const ElementId* edgeImages, const std::uint8_t* swapped, std::uint64_t eventKey, const DrawContext& event) {
    const Production& P = grammar_.productions[production];
    const ProductionOption& O = P.options[option];
    OptionFrame& F = frames_[production][option];
    changedVertices_.clear();
    changedEdges_.clear();
    // Room first: the ElementRefs below point into the graph's storage.
    graph.reserve(graph.vertices().size() + O.vertices.size(), graph.edges().size() + O.edges.size());

    // Scope shared by the option's expressions (taken before the step changes anything).
    for (std::size_t i = 0; i < P.vectors.size(); ++i) {
        const Production::Vector& v = P.vectors[i];
        const Vec2 to = graph.vertex(vertexImages[v.to]).position;
        Vec2 value = to;
        if (v.from >= 0) {
            const Vec2 from = graph.vertex(vertexImages[v.from]).position;
            value = {to.x - from.x, to.y - from.y};
        }
        F.slots[std::size_t(F.vectorSlots[i])] = Value(value);
    }
    auto refOf = [&](const Requirement& r) {
        if (r.motherIsVertex) {
            const HostVertex& v = graph.vertex(vertexImages[r.motherIndex]);
            return ElementRef{&v.attrs, true, v.position};
        }
        return ElementRef{&graph.edge(edgeImages[r.motherIndex]).attrs, false, {}};
    };
    for (std::size_t i = 0; i < O.requirementsForAll.size(); ++i) F.slots[std::size_t(F.allSlots[i])] = Value(refOf(O.requirementsForAll[i]));
    for (std::size_t i = 0; i < O.variables.size(); ++i)
        F.slots[std::size_t(F.variableSlots[i])] =
            O.variables[i].perRun ? F.runValues[i]
                                  : evaluate(O.variables[i].expression, F.slots, P, O, O.variables[i].place, Where{"variable", 0, &O.variables[i].name});

    // A new element's generation: 1 + the highest among the matched host elements.
    std::int64_t generation = 0;
    for (std::size_t i = 0; i < P.motherVertices.size(); ++i) generation = std::max(generation, graph.vertex(vertexImages[i]).generation);
    for (std::size_t j = 0; j < P.motherEdges.size(); ++j) generation = std::max(generation, graph.edge(edgeImages[j]).generation);
    generation += 1;

    std::vector<Vec2>& autoPositions = autoPositions_;
    autoPositions.assign(O.vertices.size(), Vec2{});
    bool anyNew = false;
    for (const DaughterVertex& d : O.vertices) anyNew = anyNew || d.mother < 0;
    if (anyNew) {
        const PlacementFrame frame = placementFrame(P, O, graph, vertexImages, edgeImages, swapped, placementScratch_);
        for (std::size_t i = 0; i < O.vertices.size(); ++i)
            if (O.vertices[i].mother < 0) autoPositions[i] = frame.place(O.vertices[i].position);
    }

    // `old`: the kept elements as they were.
    oldCopies_.clear();
    if (F.readsOld) oldCopies_.reserve(O.vertices.size() + O.edges.size());

    // Delete what the morphism does not keep: edges, then vertices (their edges dangle).
    std::vector<char>& keptVertex = keptVertex_;
    std::vector<char>& keptEdge = keptEdge_;
    keptVertex.assign(P.motherVertices.size(), 0);
    keptEdge.assign(P.motherEdges.size(), 0);
    for (const DaughterVertex& d : O.vertices)
        if (d.mother >= 0) keptVertex[std::size_t(d.mother)] = 1;
    for (const DaughterEdge& d : O.edges)
        if (d.mother >= 0) keptEdge[std::size_t(d.mother)] = 1;
    for (std::size_t i = 0; i < P.motherVertices.size(); ++i) changedVertices_.push_back(vertexImages[i]);
    for (std::size_t j = 0; j < P.motherEdges.size(); ++j) changedEdges_.push_back(edgeImages[j]);
    for (std::size_t j = 0; j < P.motherEdges.size(); ++j)
        if (!keptEdge[j]) graph.removeEdge(edgeImages[j]);
    for (std::size_t i = 0; i < P.motherVertices.size(); ++i)
        if (!keptVertex[i]) {
            for (ElementId e : graph.vertex(vertexImages[i]).edges) changedEdges_.push_back(e);
            graph.removeVertex(vertexImages[i]);
        }

    // Create what the daughter adds; its attributes in file order (verbatim ones now).
    auto newAttrs = [&](const std::vector<DaughterAttr>& attrs) {
        AttrMap map;
        map.entries.reserve(attrs.size() + 1);
        for (const DaughterAttr& a : attrs) map.set(a.key, a.verbatim ? a.value : Value());
        map.set(grammar_.keys.generation, Value(generation));
        return map;
    };
    std::vector<ElementId>& vertexIds = vertexIds_;
    std::vector<ElementId>& edgeIds = edgeIds_;
    vertexIds.resize(O.vertices.size());
    edgeIds.resize(O.edges.size());
    for (std::size_t i = 0; i < O.vertices.size(); ++i) {
        const DaughterVertex& d = O.vertices[i];
        if (d.mother >= 0) {
            vertexIds[i] = vertexImages[d.mother];
            if (F.readsOld) oldCopies_.push_back(graph.vertex(vertexIds[i]).attrs);
        } else {
            vertexIds[i] = graph.addVertex(autoPositions[i], newAttrs(d.attrs), generation);
            HostVertex& v = graph.vertex(vertexIds[i]);
            v.key = daughterKey(eventKey, i, false);
            v.seed = event.seed;
            v.birth = event.event;
            changedVertices_.push_back(vertexIds[i]);
        }
    }
    for (std::size_t i = 0; i < O.edges.size(); ++i) {
        const DaughterEdge& d = O.edges[i];
        const ElementId ends[2] = {d.vertex1 >= 0 ? vertexIds[std::size_t(d.vertex1)] : kNoVertex,
                                   d.vertex2 >= 0 ? vertexIds[std::size_t(d.vertex2)] : kNoVertex};
        if (d.mother >= 0) {
            // Kept: its ends follow the daughter edge's (re-attached to a new vertex where it ends at one).
            const ElementId e = edgeImages[d.mother];
            edgeIds[i] = e;
            if (F.readsOld) oldCopies_.push_back(graph.edge(e).attrs);
            const std::uint8_t s = swapped[d.mother];
            for (int k = 0; k < 2; ++k)
                if (ends[k] != kNoVertex) graph.setEnd(e, k ^ s, ends[k]);
        } else {
            edgeIds[i] = graph.addEdge(ends[0], ends[1], newAttrs(d.attrs), generation);
            HostEdge& e = graph.edge(edgeIds[i]);
            e.key = daughterKey(eventKey, i, true);
            e.seed = event.seed;
            e.birth = event.event;
            changedEdges_.push_back(edgeIds[i]);
        }
    }
    runExpressions(graph, P, O, F, vertexIds, edgeIds, vertexImages, edgeImages, autoPositions);
}

void Rewriter::runExpressions(HostGraph& graph, const Production& P, const ProductionOption& O, OptionFrame& F,
                              const std::vector<ElementId>& vertexIds, const std::vector<ElementId>& edgeIds,
                              const ElementId* vertexImages, const ElementId* edgeImages, const std::vector<Vec2>& autoPositions) {
    std::size_t oldIndex = 0;
    auto bindOwn = [&](const std::vector<Requirement>& requirements) {
        for (std::size_t k = 0; k < requirements.size(); ++k) {
            const Requirement& r = requirements[k];
            ElementRef ref;
            if (r.motherIsVertex) {
                const HostVertex& v = graph.vertex(vertexImages[r.motherIndex]);
                ref = ElementRef{&v.attrs, true, v.position};
            } else {
                ref = ElementRef{&graph.edge(edgeImages[r.motherIndex]).attrs, false, {}};
            }
            F.slots[O.sharedSlots + k] = Value(ref);
        }
    };
    for (std::size_t i = 0; i < O.vertices.size(); ++i) {
        const DaughterVertex& d = O.vertices[i];
        HostVertex& v = graph.vertex(vertexIds[i]);
        const bool isNew = d.mother < 0;
        const Vec2 position = isNew ? autoPositions[i] : v.position;
        F.slots[0] = Value(ElementRef{&v.attrs, true, position});
        F.slots[1] = !isNew && F.readsOld ? Value(ElementRef{&oldCopies_[oldIndex++], true, position}) : Value();
        bindOwn(d.requirements);
        for (const DaughterAttr& a : d.attrs)
            if (!a.verbatim) v.attrs.set(a.key, evaluate(a.expression, F.slots, P, O, a.place, Where{"daughter vertex", d.place.id, &grammar_.names.name(a.key)}));
        auto coordinate = [&](const CompiledExpression& e, const std::string& name) {
            const Value value = evaluate(e, F.slots, P, O, d.place, Where{"daughter vertex", d.place.id, &name, "at"});
            double x = 0;
            if (!numberOf(value, x))
                throw InputError(grammar_.path, placeText(d.place),
                                 "production '" + shortened(P.name) + "', option " + std::to_string(O.place.id) + ", daughter vertex " + std::to_string(d.place.id) + ", " + name + ": a number expected, not " + typeName(value));
            return x;
        };
        static const std::string kNewX = "new_x", kNewY = "new_y", kNewPos = ".new_pos";
        if (isNew && d.newX) v.position.x = coordinate(*d.newX, kNewX);
        if (isNew && d.newY) v.position.y = coordinate(*d.newY, kNewY);
        if (d.newPos) {
            const Value value = evaluate(*d.newPos, F.slots, P, O, d.place, Where{"daughter vertex", d.place.id, &kNewPos, "at"});
            const Vec2* p = value.asVec();
            if (!p)
                throw InputError(grammar_.path, placeText(d.place),
                                 "production '" + shortened(P.name) + "', option " + std::to_string(O.place.id) + ", daughter vertex " + std::to_string(d.place.id) + ", .new_pos: a vector (Vec) expected, not " + typeName(value));
            v.position = *p;
        }
    }
    for (std::size_t i = 0; i < O.edges.size(); ++i) {
        const DaughterEdge& d = O.edges[i];
        HostEdge& e = graph.edge(edgeIds[i]);
        F.slots[0] = Value(ElementRef{&e.attrs, false, {}});
        F.slots[1] = d.mother >= 0 && F.readsOld ? Value(ElementRef{&oldCopies_[oldIndex++], false, {}}) : Value();
        bindOwn(d.requirements);
        for (const DaughterAttr& a : d.attrs)
            if (!a.verbatim) e.attrs.set(a.key, evaluate(a.expression, F.slots, P, O, a.place, Where{"daughter edge", d.place.id, &grammar_.names.name(a.key)}));
    }
}

}  // namespace shapevo::graph
