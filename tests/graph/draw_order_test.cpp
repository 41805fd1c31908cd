// Tests of graph::breadthFirstOrder, the original exporter's z-order (host_graph.hpp): a layer's
// vertices before their edges, edges in attachment order (not id order), the next component from
// the oldest unvisited vertex, deleted vertices skipped, an edge with one end reached through it
// and an edge with no end last.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "graph/host_graph.hpp"

namespace draw_order_test {

using shapevo::graph::AttrMap;
using shapevo::graph::breadthFirstOrder;
using shapevo::graph::ElementId;
using shapevo::graph::HostGraph;
using shapevo::graph::kNoVertex;
using shapevo::graph::Vec2;

/// The order as text: "v0 e0 v1 ..." .
std::string orderText(const HostGraph& g) {
    std::string out;
    for (const auto& item : breadthFirstOrder(g)) {
        if (!out.empty()) out += ' ';
        out += (item.isVertex ? "v" : "e") + std::to_string(item.id);
    }
    return out;
}

ElementId vertex(HostGraph& g) { return g.addVertex(Vec2{}, AttrMap{}, 0); }

TEST(GraphDrawOrder, ALayersVerticesComeBeforeItsEdges) {
    // A cycle of four, as the Koch flake's SVG starts: circle, line, line, circle, circle, ...
    HostGraph g;
    for (int i = 0; i < 4; ++i) vertex(g);
    g.addEdge(0, 1, {}, 0);
    g.addEdge(3, 0, {}, 0);
    g.addEdge(1, 2, {}, 0);
    g.addEdge(2, 3, {}, 0);
    EXPECT_EQ(orderText(g), "v0 e0 e1 v1 v3 e2 e3 v2");
}

TEST(GraphDrawOrder, EdgesFollowAttachmentOrderNotIds) {
    HostGraph g;
    for (int i = 0; i < 3; ++i) vertex(g);
    g.addEdge(1, 2, {}, 0);  // e0, attached to v0 only later
    g.addEdge(0, 1, {}, 0);  // e1
    g.setEnd(0, 0, 0);       // e0 now runs v0 -> v2: v0's list is e1, e0
    EXPECT_EQ(orderText(g), "v0 e1 e0 v1 v2");
}

TEST(GraphDrawOrder, NextComponentStartsAtTheOldestUnvisitedVertex) {
    HostGraph g;
    for (int i = 0; i < 5; ++i) vertex(g);
    g.addEdge(3, 4, {}, 0);
    g.addEdge(0, 2, {}, 0);
    EXPECT_EQ(orderText(g), "v0 e1 v2 v1 v3 e0 v4");
}

TEST(GraphDrawOrder, DeletedVerticesAreSkippedAndEdgesWithNoEndComeLast) {
    HostGraph g;
    for (int i = 0; i < 4; ++i) vertex(g);
    g.addEdge(kNoVertex, kNoVertex, {}, 0);  // e0: no end at all
    g.addEdge(0, 1, {}, 0);                  // e1: loses v1
    g.addEdge(2, 3, {}, 0);                  // e2: loses both ends
    g.addEdge(3, 3, {}, 0);                  // e3: a loop, listed once
    g.removeVertex(1);
    g.addEdge(2, kNoVertex, {}, 0);          // e4: dangling from its birth
    g.setEnd(2, 0, kNoVertex);
    g.setEnd(2, 1, kNoVertex);
    EXPECT_EQ(orderText(g), "v0 e1 v2 e4 v3 e3 e0 e2");
}

TEST(GraphDrawOrder, RemovedEdgesAreNotDrawn) {
    HostGraph g;
    for (int i = 0; i < 2; ++i) vertex(g);
    g.addEdge(0, 1, {}, 0);
    g.addEdge(0, 1, {}, 0);
    g.removeEdge(0);
    EXPECT_EQ(orderText(g), "v0 e1 v1");
}

}  // namespace draw_order_test
