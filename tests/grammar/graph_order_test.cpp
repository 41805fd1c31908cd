// PCGR's graph order (grammar/pcg/graph_order.hpp) against the paper itself: §3.5's cyclic-edge
// search written out literally here (a recursive depth-first iteration from every node, each
// call with its own copy of the list of visited nodes, edge marks that persist) agrees with
// findCyclicEdges on 1,000 random graphs with self-loops, parallel edges and disconnected parts;
// on every one, the non-cyclic edges form an acyclic graph, order(u) < order(v) on each of them,
// source nodes come first, and the loop nodes are exactly the nodes that reach themselves.
#include <gtest/gtest.h>

#include <random>

#include "grammar/pcg/graph_order.hpp"

namespace shapevo::pcg {
namespace graph_order_test_helpers {

/// §3.5 as the paper words it: "(1) Mark all edges as unvisited and noncyclic. (2) For each graph
/// node n, perform a depth-first graph iteration starting with an empty list of visited nodes V:
/// (a) Add n to V. (b) For each unvisited outgoing edge of that node, check the destination node
/// d. (i) If d is contained in the list of visited nodes, mark the edge as cyclic. (ii) Otherwise,
/// mark the edge as visited and execute recursively at (a) with d and a copy of V."
struct LiteralSection35 {
    std::size_t nodeCount;
    const std::vector<OrderEdge>& edges;
    std::vector<bool> visited, cyclic;

    LiteralSection35(std::size_t n, const std::vector<OrderEdge>& e)
        : nodeCount(n), edges(e), visited(e.size(), false), cyclic(e.size(), false) {}

    void iterate(std::uint32_t n, std::vector<std::uint32_t> V) {  // V by value: the copy
        V.push_back(n);                                            // (a)
        for (std::size_t i = 0; i < edges.size(); ++i) {           // (b) outgoing edges, in file order
            if (edges[i].from != n || visited[i]) continue;        //     "unvisited" as of now
            const std::uint32_t d = edges[i].to;
            if (std::find(V.begin(), V.end(), d) != V.end()) {
                cyclic[i] = true;                                  // (i)
            } else {
                visited[i] = true;                                 // (ii)
                iterate(d, V);
            }
        }
    }
    std::vector<std::uint8_t> run() {
        for (std::uint32_t n = 0; n < nodeCount; ++n) iterate(n, {});
        return std::vector<std::uint8_t>(cyclic.begin(), cyclic.end());
    }
};

struct RandomGraph {
    std::size_t nodes = 0;
    std::vector<OrderEdge> edges;
};

/// 1 to 12 nodes, 0 to 3 edges a node, endpoints uniform (so self-loops, parallel edges and
/// disconnected parts all occur), ports random.
RandomGraph randomGraph(std::mt19937& rng) {
    RandomGraph g;
    g.nodes = std::uniform_int_distribution<std::size_t>(1, 12)(rng);
    const std::size_t edges = std::uniform_int_distribution<std::size_t>(0, 3 * g.nodes)(rng);
    std::uniform_int_distribution<std::uint32_t> node(0, std::uint32_t(g.nodes - 1));
    std::uniform_int_distribution<std::int32_t> port(-1, 2);
    for (std::size_t i = 0; i < edges; ++i) g.edges.push_back({node(rng), node(rng), port(rng), port(rng)});
    return g;
}

/// reach[u][v]: v can be reached from u through one edge or more among `keep`ed edges.
std::vector<std::vector<bool>> reachability(const RandomGraph& g, const std::vector<std::uint8_t>& drop) {
    std::vector<std::vector<bool>> reach(g.nodes, std::vector<bool>(g.nodes, false));
    for (std::size_t i = 0; i < g.edges.size(); ++i)
        if (!drop[i]) reach[g.edges[i].from][g.edges[i].to] = true;
    for (std::size_t k = 0; k < g.nodes; ++k)
        for (std::size_t u = 0; u < g.nodes; ++u)
            if (reach[u][k])
                for (std::size_t v = 0; v < g.nodes; ++v)
                    if (reach[k][v]) reach[u][v] = true;
    return reach;
}

}  // namespace graph_order_test_helpers

using namespace graph_order_test_helpers;

TEST(GraphOrder, CyclicEdgesAgreeWithALiteralSection35On1000RandomGraphs) {
    std::mt19937 rng(43);
    std::size_t withCycles = 0, withSelfLoops = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const RandomGraph g = randomGraph(rng);
        const std::vector<std::uint8_t> expected = LiteralSection35(g.nodes, g.edges).run();
        ASSERT_EQ(findCyclicEdges(g.nodes, g.edges), expected) << "trial " << trial;
        withCycles += std::count(expected.begin(), expected.end(), 1) > 0;
        for (const OrderEdge& e : g.edges) withSelfLoops += e.from == e.to;
    }
    EXPECT_GT(withCycles, 500u) << "the random graphs must exercise the search";
    EXPECT_GT(withSelfLoops, 100u);
}

TEST(GraphOrder, NumbersFollowEveryNonCyclicEdgeAndLeaveNoCycle) {
    std::mt19937 rng(4343);
    for (int trial = 0; trial < 1000; ++trial) {
        const RandomGraph g = randomGraph(rng);
        const GraphOrder o = graphOrder(g.nodes, g.edges);
        // removing the cyclic edges leaves an acyclic graph
        const auto reach = reachability(g, o.cyclic);
        for (std::size_t v = 0; v < g.nodes; ++v) ASSERT_FALSE(reach[v][v]) << "trial " << trial << " node " << v;
        // the numbers are 0..N-1 and follow every non-cyclic edge
        std::vector<std::uint32_t> sorted = o.order;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t v = 0; v < g.nodes; ++v) ASSERT_EQ(sorted[v], v) << "trial " << trial;
        std::vector<bool> source(g.nodes, true);
        for (std::size_t i = 0; i < g.edges.size(); ++i) {
            if (o.cyclic[i]) continue;
            source[g.edges[i].to] = false;
            ASSERT_LT(o.order[g.edges[i].from], o.order[g.edges[i].to]) << "trial " << trial << " edge " << i;
        }
        // source nodes first, in file order
        std::uint32_t next = 0;
        for (std::size_t v = 0; v < g.nodes; ++v) {
            if (source[v]) {
                ASSERT_EQ(o.order[v], next++) << "trial " << trial << " source " << v;
            }
        }
    }
}

TEST(GraphOrder, LoopNodesAreTheNodesThatReachThemselves) {
    std::mt19937 rng(434343);
    for (int trial = 0; trial < 1000; ++trial) {
        const RandomGraph g = randomGraph(rng);
        const auto reach = reachability(g, std::vector<std::uint8_t>(g.edges.size(), 0));
        const std::vector<std::uint8_t> loop = loopNodes(g.nodes, g.edges);
        for (std::size_t v = 0; v < g.nodes; ++v) ASSERT_EQ(loop[v] != 0, reach[v][v]) << "trial " << trial << " node " << v;
    }
}

TEST(GraphOrder, TiesGoByFileOrderAfterTheSources) {
    // 0 -> 2, 3 -> 1; nodes 0 and 3 are the sources; 2 and 1 become ready together: 1 first
    const std::vector<OrderEdge> edges{{0, 2}, {3, 1}};
    EXPECT_EQ(graphOrder(4, edges).order, (std::vector<std::uint32_t>{0, 2, 3, 1}));
}

TEST(GraphOrder, Fig3LikeTreeMarksTheEdgeBackIntoTheLoop) {
    // Trunk(0) -> Branch(1) -> Split(2) -> Condition(3) -> Branch (recursion), Condition -> Fruit(4)
    const std::vector<OrderEdge> edges{{0, 1}, {1, 2}, {2, 3}, {3, 1}, {3, 4}};
    const GraphOrder o = graphOrder(5, edges);
    EXPECT_EQ(o.cyclic, (std::vector<std::uint8_t>{0, 0, 0, 1, 0}));
    EXPECT_EQ(o.order, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(o.loop, (std::vector<std::uint8_t>{0, 1, 1, 1, 0}));
}

TEST(GraphOrder, VisitedMarksPersistAcrossStartNodes) {
    // The paper's marks are never reset: from node 0, 0 -> 1 and 1 -> 2 are visited and 2 -> 1 is
    // cyclic; starting again at 2, the edge 2 -> 1 is still "unvisited" (only marked cyclic) and
    // stays cyclic. With marks reset per start node, 1 -> 2 would be found cyclic from node 2.
    const std::vector<OrderEdge> edges{{0, 1}, {1, 2}, {2, 1}};
    EXPECT_EQ(findCyclicEdges(3, edges), (std::vector<std::uint8_t>{0, 0, 1}));
}

TEST(GraphOrder, AnEdgeNamingAMissingNodeIsRefused) {
    const std::vector<OrderEdge> edges{{0, 3}};
    EXPECT_THROW(findCyclicEdges(2, edges), std::out_of_range);
}

}  // namespace shapevo::pcg
