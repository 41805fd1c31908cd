// The matching budget (matcher.hpp MatchBudget, derive.hpp DeriveLimits; issue 41 "Safe"): a
// production whose mother graph has ten wildcard vertices matches a host of thousands of elements
// in combinatorially many ways; with the default limits deriveGraph must stop with an InputError
// that names the production and the budget, not hang or exhaust memory. The same for ten wildcard
// vertices in a chain of edges on a dense host. (How long it takes is measured by hand, not here.)
#include <gtest/gtest.h>

#include <string>

#include "base/input_error.hpp"
#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"

namespace graph_match_budget_test {

using namespace shapevo;
using namespace shapevo::graph;

/// A host of `hostVertices` vertices (ids 1000...), with an edge between every pair when
/// `complete`, and one production 'Many' whose mother graph has ten vertices with no condition,
/// in a chain of nine edges when `chain`, deleted by an empty daughter graph.
std::string wildcardGrammar(int hostVertices, bool complete, bool chain, bool lastNeverMatches = false) {
    std::string t = "host_graphs:\n  H:\n    id: 1\n    vertices:\n";
    for (int i = 0; i < hostVertices; ++i)
        t += "    - {id: " + std::to_string(1000 + i) + ", attr: {x: " + std::to_string(i % 60) + ", y: " + std::to_string(i / 60) + "}}\n";
    t += "    edges:\n";
    std::int64_t edgeId = 1'000'000;
    if (complete)
        for (int a = 0; a < hostVertices; ++a)
            for (int b = a + 1; b < hostVertices; ++b)
                t += "    - {id: " + std::to_string(edgeId++) + ", vertex1: " + std::to_string(1000 + a) + ", vertex2: " + std::to_string(1000 + b) + "}\n";
    t += "productions:\n  Many:\n    id: 2\n    mother_graph:\n      id: 3\n      vertices:\n";
    for (int i = 0; i < 10; ++i)
        t += "      - {id: " + std::to_string(10 + i) + ", attr: {x: " + std::to_string(i) + ", y: 0" +
             (lastNeverMatches && i == 9 ? ", mark: 'True'" : "") + "}}\n";
    t += "      edges:\n";
    if (chain)
        for (int i = 0; i < 9; ++i)
            t += "      - {id: " + std::to_string(30 + i) + ", vertex1: " + std::to_string(10 + i) + ", vertex2: " + std::to_string(11 + i) + "}\n";
    t += "    mappings:\n    - {id: 4, mother_graph: 3, daughter_graph: {id: 5}}\nresult_graphs: {}\n";
    return t;
}

void expectBudgetError(const std::string& text) {
    const GraphGrammar g = parseGraphGrammar(text, "many.yml");
    SeededDraws draws(1);
    try {
        deriveGraph(g, 0, draws);  // the default limits
        ADD_FAILURE() << "derived without reaching the matching budget";
    } catch (const InputError& e) {
        const std::string m = e.message();
        EXPECT_EQ(e.file(), "many.yml");
        EXPECT_NE(m.find("production 'Many'"), std::string::npos) << m;
        EXPECT_NE(m.find("budget"), std::string::npos) << m;
    }
}

TEST(GraphMatchBudget, TenWildcardVerticesOnThreeThousandVerticesStopWithABudgetError) {
    expectBudgetError(wildcardGrammar(3000, false, false));
}

TEST(GraphMatchBudget, AChainOfTenWildcardVerticesOnADenseHostStopsWithABudgetError) {
    // 80 vertices, every pair joined: 80 + 3160 elements, 80·79·…·71 / 2 chains.
    expectBudgetError(wildcardGrammar(80, true, true));
}

TEST(GraphMatchBudget, AChainThatNeverCompletesStopsAtTheSearchBudget) {
    // The last vertex needs a key no host vertex has: no match is ever found, so the search
    // budget (element bindings per step), not the match budget, has to stop it.
    expectBudgetError(wildcardGrammar(80, true, true, true));
}

TEST(GraphMatchBudget, ASmallerBudgetStopsSooner) {
    const GraphGrammar g = parseGraphGrammar(wildcardGrammar(50, false, false), "many.yml");
    SeededDraws draws(1);
    DeriveLimits limits;
    limits.maxMatches = 1000;
    try {
        deriveGraph(g, 0, draws, limits);
        ADD_FAILURE() << "no budget error";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("more than 1000 matches"), std::string::npos) << e.message();
    }
}

}  // namespace graph_match_budget_test
