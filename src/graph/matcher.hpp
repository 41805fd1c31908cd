// Matcher: every match of every production in the host graph, kept up to date as steps change
// it (graph-grammar README, section 2.3). A match maps the mother graph's vertices and edges
// injectively onto live host elements of the same kind, keeping incidences (not induced), with
// every element's conditions true, `.directed` mother edges running the same way, and the
// geometric ordering where the production asks for it. After a step, only matches that contain a
// changed element are dropped, and only matches that contain one are searched for (anchored at
// it): a step costs what it changed, not the size of the graph. A budget bounds what one
// production may hold and what one update may search (a mother graph of many wildcard vertices
// matches combinatorially many ways): exceeding it is an error naming the production.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "graph/draw_source.hpp"
#include "graph/graph_grammar.hpp"
#include "graph/host_graph.hpp"

namespace shapevo::graph {

struct MatchBudget {
    std::size_t maxMatches = 500'000;       // per production, held at once
    std::size_t maxSearchSteps = 20'000'000;  // element bindings tried in one update
};

/// One match, as views into the matcher's storage (valid until the next update).
struct MatchView {
    const ElementId* vertices;     // per mother vertex
    const ElementId* edges;        // per mother edge
    const std::uint8_t* swapped;   // per mother edge: 1 if mother vertex1 maps to the host edge's vertex2
    std::int64_t generationSum;
};

class Matcher {
public:
    /// `globals`: the global variables' values (conditions see them), in GraphGrammar::globals order.
    Matcher(const GraphGrammar& grammar, const HostGraph& graph, const std::vector<Value>& globals, DrawSource& draws,
            const MatchBudget& budget, bool fixGeometricOrdering);
    /// Searches the whole graph (at the start of a derivation).
    void initialize();
    /// After a step: drop the matches of every changed element, search anchored at the live ones.
    /// Each list: ids in the order they changed (duplicates allowed).
    void update(const std::vector<ElementId>& changedVertices, const std::vector<ElementId>& changedEdges);

    std::size_t count(std::size_t production) const { return productions_[production].all.size(); }
    /// The i-th match (0 <= i < count) in storage order.
    MatchView match(std::size_t production, std::size_t i) const;
    /// How many matches have the lowest generation sum, and the i-th of them.
    std::size_t oldestCount(std::size_t production) const;
    MatchView oldest(std::size_t production, std::size_t i) const;

    // --- keyed derivations (the DrawSource is keyed): firing levels -------------------------
    // Every match gets a key (lineage_key.hpp: production, images' keys, swaps, earlier firings of
    // the same match) and, when found, a firing level on its production's clock: the clock then
    // plus an exponential draw of its own. The match with the lowest level fires first; derive.hpp
    // advances the clocks so that each step picks uniformly among the applicable productions and
    // then uniformly among a production's matches, as the sequential derivation does.
    /// The live slot of `production` with the lowest level (ties: the lower key, then slot).
    std::uint32_t earliest(std::size_t production) const;
    MatchView slotView(std::size_t production, std::uint32_t slot) const { return view(production, slot); }
    double level(std::size_t production, std::uint32_t slot) const { return productions_[production].stored[slot].level; }
    std::uint64_t key(std::size_t production, std::uint32_t slot) const { return productions_[production].stored[slot].key; }
    /// The slots with the lowest generation sum.
    const std::vector<std::uint32_t>& oldestSlots(std::size_t production) const { return productions_[production].buckets.begin()->second; }
    double clock(std::size_t production) const { return clocks_[production]; }
    void advanceClock(std::size_t production, double by) { clocks_[production] += by; }
    /// How many times the match of key `matchKey` fired so far; fired() counts one more.
    std::uint32_t firings(std::uint64_t matchKey) const {
        const auto it = fired_.find(matchKey);
        return it == fired_.end() ? 0 : it->second;
    }
    void fired(std::uint64_t matchKey) { ++fired_[matchKey]; }

private:
    /// One binding of a search plan (from an anchor, the rest of the mother graph).
    struct Step {
        enum Kind : std::uint8_t { VertexAtEdgeEnd, EdgeAtVertex, AnyVertex, AnyEdge } kind;
        int mother = 0;  // the mother element this step binds
        int via = 0;     // VertexAtEdgeEnd: the bound mother edge; EdgeAtVertex: the bound mother vertex
        int end = 0;     // the end of the mother edge that `via` / the new vertex is
    };
    struct Stored {
        bool alive = false;
        std::uint32_t serial = 0;
        std::int64_t generationSum = 0;
        std::uint32_t positionInAll = 0, positionInBucket = 0;
        std::uint64_t key = 0;  // keyed derivations: the match's key and firing level
        double level = 0;
    };
    struct PerProduction {
        std::size_t vertexCount = 0, edgeCount = 0;
        bool geometric = false;
        std::array<std::vector<std::uint32_t>, 2> axisRanks;  // per mother vertex, its rank along x and y
        std::vector<std::vector<Step>> plans;  // per anchor: mother vertices, then mother edges
        std::vector<Stored> stored;
        std::vector<ElementId> images;          // stride vertexCount + edgeCount
        std::vector<std::uint8_t> swapped;      // stride edgeCount
        std::vector<std::uint32_t> freeSlots;
        std::vector<std::uint32_t> all;         // live slots
        std::map<std::int64_t, std::vector<std::uint32_t>> buckets;  // generation sum -> live slots
    };
    /// The matches an element is in: a singly linked list per element in one pool (no allocation
    /// per element); entries of dropped matches are skipped by their serial, a list is cut when its
    /// element changes, and the pool is reused by the next derivation.
    struct SlotRef {
        std::uint32_t production, slot, serial, next;
    };

    void buildPlans();
    void searchFrom(bool isVertex, ElementId anchor, std::uint32_t rank);
    bool extend(std::size_t p, const std::vector<Step>& plan, std::size_t step, std::uint32_t rank);
    void countSearchStep(std::size_t p);
    bool vertexFits(std::size_t p, int mother, ElementId host);
    bool edgeFits(std::size_t p, int mother, ElementId host, std::uint8_t swapped);
    bool conditionsHold(const std::vector<MatchCondition>& conditions, const AttrMap& attrs, ElementRef element, const Production& production);
    /// Keyed: condition draws of production `p` on an element belong to the element.
    void enterConditionContext(std::size_t p, std::uint64_t elementKey, std::uint64_t seed, std::uint32_t birth);
    /// Keyed: the key and firing level of the match being recorded.
    void keyMatch(std::size_t p, Stored& s);
    bool geometricOrderHolds(std::size_t p) const;
    void record(std::size_t p, std::uint32_t rank);
    void remove(std::size_t p, std::uint32_t slot);
    void dropMatchesOf(std::vector<std::uint32_t>& heads, ElementId id);
    void link(std::vector<std::uint32_t>& heads, ElementId id, const SlotRef& ref);
    MatchView view(std::size_t p, std::uint32_t slot) const;

    const GraphGrammar& grammar_;
    const HostGraph& graph_;
    DrawSource& draws_;
    MatchBudget budget_;
    bool fixGeometricOrdering_;
    std::vector<PerProduction> productions_;
    std::vector<SlotRef> links_;                                      // the lists' pool
    std::vector<std::uint32_t> vertexMatches_, edgeMatches_;          // per host element: its list's head
    std::vector<std::uint32_t> vertexRank_, edgeRank_;               // changed-order rank this update
    std::vector<Value> conditionFrame_;                               // attr, attrs, globals...
    // The match being built.
    std::vector<ElementId> boundVertices_, boundEdges_;
    std::vector<std::uint8_t> boundSwapped_;
    std::size_t searchSteps_ = 0;
    bool keyed_ = false;
    std::vector<double> clocks_;                            // keyed: per production
    std::unordered_map<std::uint64_t, std::uint32_t> fired_;  // keyed: firings per match key
    std::uint32_t currentRank_ = 0;  // the rank of the anchor being searched from
};

}  // namespace shapevo::graph
