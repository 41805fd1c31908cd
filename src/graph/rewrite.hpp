// Rewriter: one application of a production's option at a match — the single push-out of
// graph-grammar README section 2.4 (unmapped mother images deleted, their edges left dangling;
// unmapped daughter elements created; kept edges re-attached to the daughter's ends), automatic
// positions (auto_position.hpp), then every daughter expression in file order with its scope
// (section 2.5). It reports which host elements the step changed, for the matcher.
#pragma once
#include <vector>

#include "graph/auto_position.hpp"
#include "graph/draw_source.hpp"
#include "graph/graph_grammar.hpp"
#include "graph/host_graph.hpp"

namespace shapevo::graph {

class Rewriter {
public:
    /// `globals`: the global variables' values. Evaluates every option's `run` variables now.
    Rewriter(const GraphGrammar& grammar, const std::vector<Value>& globals, DrawSource& draws);

    /// Applies option `option` of production `production` at the match (per mother vertex and
    /// edge). The elements it creates take their lineage from the event: key
    /// daughterKey(eventKey, index), `event`'s seed and step. Throws InputError naming the place of
    /// an expression that fails.
    void apply(HostGraph& graph, std::size_t production, std::size_t option, const ElementId* vertexImages,
               const ElementId* edgeImages, const std::uint8_t* swapped, std::uint64_t eventKey = 0,
               const DrawContext& event = {});

    /// What the last apply changed (kept, new, deleted, re-attached, left dangling).
    const std::vector<ElementId>& changedVertices() const { return changedVertices_; }
    const std::vector<ElementId>& changedEdges() const { return changedEdges_; }

private:
    struct OptionFrame {
        std::vector<Value> slots;
        std::vector<int> vectorSlots, allSlots, variableSlots;
        std::vector<Value> runValues;  // per variable (perRun only)
        bool readsOld = false;
    };
    /// What an expression belongs to, put into words only when it fails.
    struct Where {
        const char* kind;                // "daughter vertex", "variable", ...
        std::int64_t id = 0;             // the element's file id, or 0
        const std::string* name = nullptr;  // the attribute or variable
        const char* nameKind = "attribute";
    };
    Value evaluate(const CompiledExpression& e, std::vector<Value>& slots, const Production& p, const ProductionOption& o,
                   const FilePlace& place, const Where& where);
    void runExpressions(HostGraph& graph, const Production& p, const ProductionOption& o, OptionFrame& frame,
                        const std::vector<ElementId>& vertexIds, const std::vector<ElementId>& edgeIds,
                        const ElementId* vertexImages, const ElementId* edgeImages, const std::vector<Vec2>& autoPositions);

    const GraphGrammar& grammar_;
    DrawSource& draws_;
    std::vector<std::vector<OptionFrame>> frames_;  // per production, per option
    std::vector<ElementId> changedVertices_, changedEdges_;
    std::vector<AttrMap> oldCopies_;
    // Scratch kept between steps (a step allocates only the elements it adds).
    std::vector<Vec2> autoPositions_;
    std::vector<char> keptVertex_, keptEdge_;
    std::vector<ElementId> vertexIds_, edgeIds_;
    PlacementScratch placementScratch_;
};

}  // namespace shapevo::graph
