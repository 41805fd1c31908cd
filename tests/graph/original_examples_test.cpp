// The four example files of the original tool (read from ../shared/graph-grammar/original-examples,
// never copied into the project; skipped with a message where absent), derived for many seeds and
// step counts, checking the invariants the original shows (graph-grammar README, section 5).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"
#include "seeded_derivation.hpp"

namespace original_examples_test {

using namespace shapevo::graph;

std::string examplePath(const std::string& name) {
    return std::string(SHAPEVO_SOURCE_DIR) + "/../shared/graph-grammar/original-examples/" + name;
}

#define SKIP_WITHOUT(path)                                                                                              \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "the original example " << path << " is absent (it is read, " \
                                                        "never copied into the project)"

using test_support::deriveSeeded;

std::size_t firedOf(const GraphGrammar& g, const DeriveResult& r, const std::string& name) {
    for (std::size_t p = 0; p < g.productions.size(); ++p)
        if (g.productions[p].name == name) return std::size_t(r.fired[p]);
    ADD_FAILURE() << "no production " << name;
    return 0;
}

TEST(GraphOriginalExamples, KochFlakeHasSixPlusSixElementsPerStep) {
    const std::string path = examplePath("koch_flake.yml");
    SKIP_WITHOUT(path);
    const GraphGrammar g = readGraphGrammar(path);
    for (std::uint64_t seed : {1, 2, 3, 99})
        for (std::int64_t steps : {0, 1, 7, 64, 192}) {
            if (steps == 0) continue;
            const DeriveResult r = deriveSeeded(g, seed, steps);
            EXPECT_EQ(r.steps, steps);
            EXPECT_EQ(r.graph.elements(), std::size_t(6 + 6 * steps)) << "seed " << seed << ", " << steps << " steps";
            EXPECT_EQ(r.graph.liveVertices(), r.graph.liveEdges());
            EXPECT_EQ(r.graph.danglingEdges(), 0u);
        }
}

TEST(GraphOriginalExamples, TreeHasThreePlusFourElementsPerStepAndTenTrunkSteps) {
    const std::string path = examplePath("tree.yml");
    SKIP_WITHOUT(path);
    const GraphGrammar g = readGraphGrammar(path);
    for (std::uint64_t seed : {1, 2, 3, 4, 5})
        for (std::int64_t steps : {60, 120, 200}) {
            const DeriveResult r = deriveSeeded(g, seed, steps);
            EXPECT_EQ(r.steps, steps);
            EXPECT_EQ(r.graph.elements(), std::size_t(3 + 4 * steps)) << "seed " << seed;
            EXPECT_EQ(firedOf(g, r, "Grow Trunk"), 10u) << "seed " << seed << ", " << steps << " steps";
        }
}

TEST(GraphOriginalExamples, CircleRunsThreeNPlusOneStepsToTwoNPlusTwoElements) {
    const std::string path = examplePath("pattern_circle.yml");
    SKIP_WITHOUT(path);
    const GraphGrammar g = readGraphGrammar(path);
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed, 0);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        ASSERT_EQ((r.steps - 1) % 3, 0) << "seed " << seed << ": " << r.steps << " steps";
        const std::int64_t n = (r.steps - 1) / 3;
        EXPECT_GE(n, 5);
        EXPECT_LE(n, 15);
        EXPECT_EQ(r.graph.elements(), std::size_t(2 * n + 2)) << "seed " << seed;
    }
}

TEST(GraphOriginalExamples, SquareStepsAndElementsFollowItsTwoGlobals) {
    const std::string path = examplePath("pattern_square.yml");
    SKIP_WITHOUT(path);
    const GraphGrammar g = readGraphGrammar(path);
    int seen = 0;
    for (std::uint64_t seed = 1; seed <= 24; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed, 500);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal) << "seed " << seed;
        // steps = 54 + 16L + 32D and elements = 160 + 48(L-1) + 64D for some L in [1,4], D in [0,2].
        bool found = false;
        for (int L = 1; L <= 4; ++L)
            for (int D = 0; D <= 2; ++D)
                found = found || (r.steps == 54 + 16 * L + 32 * D && r.graph.elements() == std::size_t(160 + 48 * (L - 1) + 64 * D));
        EXPECT_TRUE(found) << "seed " << seed << ": " << r.steps << " steps, " << r.graph.elements() << " elements";
        seen += found;
    }
    EXPECT_EQ(seen, 24);
}

}  // namespace original_examples_test
