// deriveGraph: the step loop of a derivation (derive.hpp) — choices here, matching in
// matcher.cpp, the push-out in rewrite.cpp.
#include "graph/derive.hpp"

#include <algorithm>
#include <map>

#include "base/input_error.hpp"
#include "graph/matcher.hpp"
#include "graph/rewrite.hpp"

namespace shapevo::graph {

namespace {

std::vector<Value> evaluateGlobals(const GraphGrammar& g, DrawSource& draws) {
    std::vector<Value> values;
    for (const GlobalVariable& v : g.globals) {
        const EvaluationFrame frame{nullptr, 0, &g.names, &draws};
        try {
            values.push_back(v.expression.evaluate(frame));
        } catch (const EvaluationError& e) {
            throw InputError(g.path, std::to_string(v.place.line) + ":" + std::to_string(v.place.column),
                             "global variable '" + shortened(v.name) + "': " + e.what());
        }
    }
    return values;
}

/// An option by weight (every weight 0: the first).
std::size_t drawOption(const Production& p, DrawSource& draws) {
    if (p.options.size() == 1) return 0;
    std::uint64_t total = 0;
    for (const ProductionOption& o : p.options) total += std::uint64_t(o.weight);
    if (total == 0) return 0;
    std::uint64_t r = draws.below(total, DrawPurpose::Option);
    for (std::size_t i = 0; i < p.options.size(); ++i) {
        if (r < std::uint64_t(p.options[i].weight)) return i;
        r -= std::uint64_t(p.options[i].weight);
    }
    return p.options.size() - 1;
}

}  // namespace

DeriveResult deriveGraph(const GraphGrammar& grammar, std::size_t host, DrawSource& draws, const DeriveLimits& limits) {
    DeriveResult result;
    result.graph = grammar.hosts.at(host).graph;
    result.fired.assign(grammar.productions.size(), 0);
    HostGraph& graph = result.graph;
    const std::vector<Value> globals = evaluateGlobals(grammar, draws);
    Rewriter rewriter(grammar, globals, draws);
    Matcher matcher(grammar, graph, globals, draws, MatchBudget{limits.maxMatches, limits.maxSearchSteps}, limits.fixGeometricOrdering);
    matcher.initialize();

    // Priorities from the lowest up, with their productions in file order and their limits.
    std::map<int, std::vector<std::size_t>> byPriority;
    for (std::size_t p = 0; p < grammar.productions.size(); ++p) byPriority[grammar.productions[p].priority].push_back(p);
    struct Level {
        std::vector<std::size_t> productions;
        std::int64_t limit = -1, steps = 0;
    };
    std::vector<Level> levels;
    for (auto& [priority, productions] : byPriority) {
        Level level{productions};
        for (const auto& [pr, limit] : grammar.priorityLimits)
            if (pr == priority) level.limit = limit;
        levels.push_back(std::move(level));
    }
    const std::int64_t stepLimit = limits.maxSteps > 0 ? limits.maxSteps : grammar.globalLimit;
    std::vector<std::size_t> applicable;
    std::vector<ElementId> vertexImages, edgeImages;
    std::vector<std::uint8_t> swapped;
    for (;;) {
        if (stepLimit > 0 && result.steps >= stepLimit) {
            result.stop = DeriveResult::Stop::StepLimit;
            break;
        }
        Level* chosenLevel = nullptr;
        std::size_t production = 0;
        for (Level& level : levels) {
            if (level.limit >= 0 && level.steps >= level.limit) continue;
            applicable.clear();
            for (std::size_t p : level.productions)
                if (matcher.count(p) > 0) applicable.push_back(p);
            if (applicable.empty()) continue;
            production = applicable.size() == 1 ? applicable[0] : applicable[draws.below(applicable.size(), DrawPurpose::Production)];
            chosenLevel = &level;
            break;
        }
        if (!chosenLevel) break;  // terminal
        const Production& P = grammar.productions[production];
        // The original draws the option twice: once to filter matches, once to apply.
        const std::size_t filterOption = drawOption(P, draws);
        MatchView m{};
        if (P.options[filterOption].oldest) {
            const std::size_t n = matcher.oldestCount(production);
            m = matcher.oldest(production, n == 1 ? 0 : draws.below(n, DrawPurpose::Match));
        } else {
            const std::size_t n = matcher.count(production);
            m = matcher.match(production, n == 1 ? 0 : draws.below(n, DrawPurpose::Match));
        }
        const std::size_t applyOption = limits.drawOptionOnce ? filterOption : drawOption(P, draws);
        vertexImages.assign(m.vertices, m.vertices + P.motherVertices.size());
        edgeImages.assign(m.edges, m.edges + P.motherEdges.size());
        swapped.assign(m.swapped, m.swapped + P.motherEdges.size());
        rewriter.apply(graph, production, applyOption, vertexImages.data(), edgeImages.data(), swapped.data());
        ++result.steps;
        ++result.fired[production];
        ++chosenLevel->steps;
        if (graph.elements() > limits.maxElements)
            throw InputError(grammar.path, "", "the derivation passed " + std::to_string(limits.maxElements) + " elements at step " +
                                                   std::to_string(result.steps) + " (production '" + shortened(P.name) +
                                                   "'); give fewer steps or raise the element limit");
        matcher.update(rewriter.changedVertices(), rewriter.changedEdges());
    }
    return result;
}

}  // namespace shapevo::graph
