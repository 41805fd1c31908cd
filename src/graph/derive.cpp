// deriveGraph: the step loop of a derivation (derive.hpp) — choices here, matching in
// matcher.cpp, the push-out in rewrite.cpp.
#include "graph/derive.hpp"

#include <algorithm>
#include <map>

#include "base/input_error.hpp"
#include "graph/lineage_key.hpp"
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

namespace {

/// One step's choice: the production, the match, the option applied and the event's lineage.
struct StepChoice {
    std::size_t production = 0;
    MatchView match{};
    std::size_t option = 0;
    std::uint64_t eventKey = 0;
    DrawContext event;
};

/// The sequential choice (README section 2): a uniform applicable production, the option by
/// weight (drawn twice, as the original does, unless drawOptionOnce), a uniform match or a
/// uniform one among the oldest.
StepChoice chooseSequential(const GraphGrammar& grammar, const std::vector<std::size_t>& applicable, const Matcher& matcher,
                            DrawSource& draws, const DeriveLimits& limits) {
    StepChoice c;
    c.production = applicable.size() == 1 ? applicable[0] : applicable[draws.below(applicable.size(), DrawPurpose::Production)];
    const Production& P = grammar.productions[c.production];
    const std::size_t filterOption = drawOption(P, draws);
    if (P.options[filterOption].oldest) {
        const std::size_t n = matcher.oldestCount(c.production);
        c.match = matcher.oldest(c.production, n == 1 ? 0 : draws.below(n, DrawPurpose::Match));
    } else {
        const std::size_t n = matcher.count(c.production);
        c.match = matcher.match(c.production, n == 1 ? 0 : draws.below(n, DrawPurpose::Match));
    }
    c.option = limits.drawOptionOnce ? filterOption : drawOption(P, draws);
    return c;
}

/// An option by weight from one keyed word.
std::size_t optionOf(const Production& p, std::uint64_t word) {
    std::uint64_t total = 0;
    for (const ProductionOption& o : p.options) total += std::uint64_t(o.weight);
    if (p.options.size() == 1 || total == 0) return 0;
    std::uint64_t r = wordBelow(word, total);
    for (std::size_t i = 0; i < p.options.size(); ++i) {
        if (r < std::uint64_t(p.options[i].weight)) return i;
        r -= std::uint64_t(p.options[i].weight);
    }
    return p.options.size() - 1;
}

/// The lineage parent of a match: its youngest element's seed and event (the first on ties).
DrawContext parentOf(const HostGraph& graph, const Production& P, const MatchView& m, std::uint64_t rootSeed) {
    DrawContext parent{rootSeed, 0};
    bool first = true;
    auto take = [&](std::uint64_t seed, std::uint32_t birth) {
        if (first || birth > parent.event) parent = DrawContext{seed, birth};
        first = false;
    };
    for (std::size_t i = 0; i < P.motherVertices.size(); ++i) take(graph.vertex(m.vertices[i]).seed, graph.vertex(m.vertices[i]).birth);
    for (std::size_t j = 0; j < P.motherEdges.size(); ++j) take(graph.edge(m.edges[j]).seed, graph.edge(m.edges[j]).birth);
    return parent;
}

/// The keyed choice (matcher.hpp, firing levels): each applicable production fires after
/// (its earliest match's level - its clock) x its match count — an exponential wait of mean 1 — so
/// the first is uniform among them; its earliest match is uniform among its matches. The clocks
/// of the applicable productions advance by the wait over their match counts. Options and the pick
/// among the oldest are keyed by the match; the event's seed may be the genome's own.
StepChoice chooseKeyed(const GraphGrammar& grammar, const HostGraph& graph, const std::vector<std::size_t>& applicable,
                       Matcher& matcher, DrawSource& draws, const DeriveLimits& limits, std::uint32_t event) {
    StepChoice c;
    double wait = 0;
    std::uint32_t slot = 0;
    for (std::size_t k = 0; k < applicable.size(); ++k) {
        const std::size_t p = applicable[k];
        const std::uint32_t s = matcher.earliest(p);
        const double w = (matcher.level(p, s) - matcher.clock(p)) * double(matcher.count(p));
        if (k == 0 || w < wait) wait = w, c.production = p, slot = s;
    }
    for (std::size_t p : applicable) matcher.advanceClock(p, wait / double(matcher.count(p)));
    const Production& P = grammar.productions[c.production];
    const std::uint64_t rootSeed = draws.rootSeed();
    std::uint64_t matchKey = matcher.key(c.production, slot);
    DrawContext parent = parentOf(graph, P, matcher.slotView(c.production, slot), rootSeed);
    const std::size_t filterOption = optionOf(P, draws.word(mixKey(matchKey, key_tag::kFilterOption), parent, DrawPurpose::Option));
    if (P.options[filterOption].oldest) {
        std::uint64_t best = 0;
        bool first = true;
        for (std::uint32_t s : matcher.oldestSlots(c.production)) {
            const std::uint64_t key = matcher.key(c.production, s);
            const DrawContext at = parentOf(graph, P, matcher.slotView(c.production, s), rootSeed);
            const std::uint64_t w = draws.word(mixKey(key, key_tag::kOldest), at, DrawPurpose::Match);
            if (first || w < best || (w == best && key < matchKey)) best = w, slot = s, matchKey = key, parent = at;
            first = false;
        }
    }
    c.match = matcher.slotView(c.production, slot);
    c.eventKey = mixKey(matchKey, matcher.firings(matchKey));
    matcher.fired(matchKey);
    c.event.event = event;
    c.event.seed = draws.eventSeed(c.eventKey, mixKey(c.eventKey, key_tag::kSalt), parent.seed, event, parent.event);
    c.option = limits.drawOptionOnce ? filterOption : optionOf(P, draws.word(mixKey(c.eventKey, key_tag::kApplyOption), c.event, DrawPurpose::Option));
    draws.enterContext(mixKey(c.eventKey, key_tag::kExpressions), c.event);
    return c;
}

}  // namespace

DeriveResult deriveGraph(const GraphGrammar& grammar, std::size_t host, DrawSource& draws, const DeriveLimits& limits) {
    DeriveResult result;
    result.graph = grammar.hosts.at(host).graph;
    result.fired.assign(grammar.productions.size(), 0);
    HostGraph& graph = result.graph;
    const bool keyed = draws.keyed();
    const std::uint64_t rootSeed = keyed ? draws.rootSeed() : 0;
    for (ElementId v = 0; v < graph.vertices().size(); ++v) {
        graph.vertex(v).key = hostElementKey(host, v, false);
        graph.vertex(v).seed = rootSeed;
    }
    for (ElementId e = 0; e < graph.edges().size(); ++e) {
        graph.edge(e).key = hostElementKey(host, e, true);
        graph.edge(e).seed = rootSeed;
    }
    if (keyed) draws.enterContext(key_tag::kGlobals, DrawContext{rootSeed, 0});
    const std::vector<Value> globals = evaluateGlobals(grammar, draws);
    if (keyed) draws.enterContext(key_tag::kRunVariables, DrawContext{rootSeed, 0});
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
        for (Level& level : levels) {
            if (level.limit >= 0 && level.steps >= level.limit) continue;
            applicable.clear();
            for (std::size_t p : level.productions)
                if (matcher.count(p) > 0) applicable.push_back(p);
            if (applicable.empty()) continue;
            chosenLevel = &level;
            break;
        }
        if (!chosenLevel) break;  // terminal
        const StepChoice c = keyed ? chooseKeyed(grammar, graph, applicable, matcher, draws, limits, std::uint32_t(result.steps + 1))
                                   : chooseSequential(grammar, applicable, matcher, draws, limits);
        const Production& P = grammar.productions[c.production];
        vertexImages.assign(c.match.vertices, c.match.vertices + P.motherVertices.size());
        edgeImages.assign(c.match.edges, c.match.edges + P.motherEdges.size());
        swapped.assign(c.match.swapped, c.match.swapped + P.motherEdges.size());
        rewriter.apply(graph, c.production, c.option, vertexImages.data(), edgeImages.data(), swapped.data(), c.eventKey, c.event);
        ++result.steps;
        ++result.fired[c.production];
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
