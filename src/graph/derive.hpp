// deriveGraph: one derivation of a 2D graph grammar (graph-grammar README, section 2): globals,
// then steps — the lowest applicable priority, a uniform applicable production, an option by
// weight, a match (uniform, or among the oldest), the single push-out, automatic positions — until
// no production applies or a limit is reached. Matching is incremental: a step re-examines only
// what it changed, so a step's cost does not grow with the graph. Every decision comes from a
// DrawSource, every iteration is in creation order: one seed, one graph, on every machine.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "graph/draw_source.hpp"
#include "graph/graph_grammar.hpp"
#include "graph/host_graph.hpp"

namespace shapevo::graph {

struct DeriveLimits {
    std::int64_t maxSteps = 0;               // 0: the file's options.max_derivations.all, or none
    std::size_t maxElements = 1'000'000;     // a derivation that would exceed it stops with an error
    std::size_t maxMatches = 500'000;        // matches one production may hold at once (~100 MB)
    std::size_t maxSearchSteps = 20'000'000; // element bindings one step's matching may try (~1 s)
    // The original's quirks are reproduced by default (they change results); each fix is a switch.
    bool fixGeometricOrdering = false;       // compare with the nearest mapped vertex after, not the farthest
    bool drawOptionOnce = false;             // one option draw filters the matches and is applied
};

struct DeriveResult {
    HostGraph graph;
    std::int64_t steps = 0;
    std::vector<std::int64_t> fired;  // per production, how many times it was applied
    enum class Stop : std::uint8_t { Terminal, StepLimit } stop = Stop::Terminal;
};

/// Derives from host graph `host` (index into grammar.hosts). Throws InputError (naming the
/// file, production and element) when an expression fails or a limit of `limits` is exceeded.
DeriveResult deriveGraph(const GraphGrammar& grammar, std::size_t host, DrawSource& draws, const DeriveLimits& limits = {});

}  // namespace shapevo::graph
