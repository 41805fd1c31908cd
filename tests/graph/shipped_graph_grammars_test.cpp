// The graph grammars shipped in grammars/graph/ (written from the paper's prose), each derived
// for many seeds: each derives without error to its end or its step limit, and shows the structure
// its header comment promises (counts fixed by its rules, geometry its productions construct).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "graph/derive.hpp"
#include "graph/read_graph_grammar.hpp"
#include "seeded_derivation.hpp"

namespace shipped_graph_grammars_test {

using namespace shapevo::graph;

GraphGrammar shipped(const std::string& name) {
    return readGraphGrammar(std::string(SHAPEVO_SOURCE_DIR) + "/grammars/graph/" + name);
}

using test_support::deriveSeeded;

std::int64_t firedOf(const GraphGrammar& g, const DeriveResult& r, const std::string& name) {
    for (std::size_t p = 0; p < g.productions.size(); ++p)
        if (g.productions[p].name == name) return r.fired[p];
    ADD_FAILURE() << "no production " << name;
    return -1;
}

const Value* attrOf(const GraphGrammar& g, const AttrMap& m, const char* key) {
    const AttrKey k = g.names.find(key);
    return k == AttrNames::kNone ? nullptr : m.find(k);
}

double numberAttr(const GraphGrammar& g, const AttrMap& m, const char* key) {
    const Value* v = attrOf(g, m, key);
    double x = std::nan("");
    if (!v || !numberOf(*v, x)) ADD_FAILURE() << "no number attribute " << key;
    return x;
}

bool textAttrIs(const GraphGrammar& g, const AttrMap& m, const char* key, const std::string& text) {
    const Value* v = attrOf(g, m, key);
    return v && v->asString() && *v->asString() == text;
}

bool hasAttr(const GraphGrammar& g, const AttrMap& m, const char* key) { return attrOf(g, m, key) != nullptr; }

double lengthOf(const HostGraph& graph, const HostEdge& e) {
    const Vec2 a = graph.vertex(e.vertex1).position, b = graph.vertex(e.vertex2).position;
    return std::hypot(b.x - a.x, b.y - a.y);
}

// --- koch.yml ---------------------------------------------------------------------------------

TEST(ShippedGraphGrammars, KochHasSixPlusSixElementsPerStepAndStopsAtItsLimit) {
    const GraphGrammar g = shipped("koch.yml");
    for (std::uint64_t seed = 1; seed <= 50; ++seed)
        for (std::int64_t steps : {0, 1, 7, 200}) {
            const DeriveResult r = deriveSeeded(g, seed, steps);
            const std::int64_t expected = steps == 0 ? 63 : steps;  // 0: the file's max_derivations.all
            EXPECT_EQ(r.stop, DeriveResult::Stop::StepLimit);
            EXPECT_EQ(r.steps, expected);
            EXPECT_EQ(r.graph.elements(), std::size_t(6 + 6 * expected)) << "seed " << seed;
            EXPECT_EQ(r.graph.danglingEdges(), 0u);
        }
}

TEST(ShippedGraphGrammars, KochOutlineStaysOneClosedDirectedLoop) {
    const GraphGrammar g = shipped("koch.yml");
    for (std::uint64_t seed : {1, 2, 3}) {
        const DeriveResult r = deriveSeeded(g, seed, 100);
        const HostGraph& graph = r.graph;
        std::vector<int> out(graph.vertices().size(), 0), in(graph.vertices().size(), 0);
        std::vector<ElementId> next(graph.vertices().size(), kNoVertex);
        for (const HostEdge& e : graph.edges())
            if (e.alive) ++out[e.vertex1], ++in[e.vertex2], next[e.vertex1] = e.vertex2;
        std::size_t alive = 0;
        for (std::size_t v = 0; v < graph.vertices().size(); ++v)
            if (graph.vertex(ElementId(v)).alive) {
                ++alive;
                EXPECT_EQ(out[v], 1);
                EXPECT_EQ(in[v], 1);
            }
        std::size_t loop = 1;
        for (ElementId v = next[0]; v != 0 && loop <= alive; v = next[v]) ++loop;
        EXPECT_EQ(loop, alive) << "seed " << seed << ": the outline is not one loop";
    }
}

TEST(ShippedGraphGrammars, KochSegmentsAreThirdsAndEachEarlyLevelIsCompletedOldestFirst) {
    const GraphGrammar g = shipped("koch.yml");
    const double side = 3.0 * std::sqrt(3.0);
    for (std::uint64_t seed : {1, 5, 9}) {
        // Every segment is side / 3^k: the apex sits at the true Koch height.
        const DeriveResult r = deriveSeeded(g, seed, 255);
        for (const HostEdge& e : r.graph.edges()) {
            if (!e.alive) continue;
            const double level = std::log(side / lengthOf(r.graph, e)) / std::log(3.0);
            EXPECT_NEAR(level, std::round(level), 1e-9) << "seed " << seed;
        }
        // After 3 and 3 + 12 steps, level 1 and level 2 are complete: all segments equal.
        for (std::int64_t steps : {3, 15}) {
            const DeriveResult full = deriveSeeded(g, seed, steps);
            const double expected = side / (steps == 3 ? 3.0 : 9.0);
            for (const HostEdge& e : full.graph.edges())
                if (e.alive) EXPECT_NEAR(lengthOf(full.graph, e), expected, 1e-9) << "seed " << seed << ", " << steps << " steps";
        }
    }
}

// --- tree.yml ---------------------------------------------------------------------------------

TEST(ShippedGraphGrammars, TreeGrowsItsTrunkSevenTimesCrownsOnceAndEndsAfter143Steps) {
    const GraphGrammar g = shipped("tree.yml");
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        EXPECT_EQ(r.steps, 143) << "seed " << seed;
        EXPECT_EQ(firedOf(g, r, "Grow trunk"), 7);
        EXPECT_EQ(firedOf(g, r, "Crown"), 1);
        EXPECT_EQ(firedOf(g, r, "Fork"), 135);
        EXPECT_EQ(r.graph.elements(), std::size_t(3 + 4 * r.steps));
    }
    for (std::int64_t steps : {1, 8, 50, 100})  // a step limit stops it part way, 4 elements a step
        EXPECT_EQ(deriveSeeded(g, 3, steps).graph.elements(), std::size_t(3 + 4 * steps));
}

TEST(ShippedGraphGrammars, TreeBranchesGetThinnerAndEndInLeaves) {
    const GraphGrammar g = shipped("tree.yml");
    const AttrKey width = g.names.find(".svg_stroke_width");
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        const HostGraph& graph = r.graph;
        std::vector<ElementId> incoming(graph.vertices().size(), kNoVertex);
        std::vector<int> outgoing(graph.vertices().size(), 0);
        for (std::size_t e = 0; e < graph.edges().size(); ++e)
            if (graph.edge(ElementId(e)).alive) {
                incoming[graph.edge(ElementId(e)).vertex2] = ElementId(e);
                ++outgoing[graph.edge(ElementId(e)).vertex1];
            }
        for (const HostEdge& e : graph.edges()) {
            if (!e.alive || incoming[e.vertex1] == kNoVertex) continue;  // the first trunk segment
            double child = 0, parent = 0;
            ASSERT_TRUE(numberOf(*e.attrs.find(width), child));
            ASSERT_TRUE(numberOf(*graph.edge(incoming[e.vertex1]).attrs.find(width), parent));
            EXPECT_LT(child, parent) << "seed " << seed;
        }
        std::size_t leaves = 0;
        for (std::size_t v = 0; v < graph.vertices().size(); ++v)
            if (outgoing[v] == 0) {
                ++leaves;
                EXPECT_TRUE(textAttrIs(g, graph.vertex(ElementId(v)).attrs, ".svg_tag", "circle")) << "a leaf is drawn as a disc";
            }
        EXPECT_EQ(leaves, 9u * 16u) << "seed " << seed << ": 9 branches of depth 1, each ending in 16 leaves";
    }
}

// --- radial.yml -------------------------------------------------------------------------------

TEST(ShippedGraphGrammars, RadialHasAsManyPetalsAsItsGlobalDraws) {
    const GraphGrammar g = shipped("radial.yml");
    std::set<std::int64_t> seen;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        const AttrMap& centre = r.graph.vertex(0).attrs;
        const std::int64_t n = std::int64_t(numberAttr(g, centre, "target"));
        seen.insert(n);
        EXPECT_GE(n, 5);
        EXPECT_LE(n, 12);
        std::int64_t spokes = 0;
        for (const HostEdge& e : r.graph.edges()) spokes += e.alive && textAttrIs(g, e.attrs, "kind", "spoke");
        EXPECT_EQ(spokes, n) << "seed " << seed;
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        EXPECT_EQ(r.steps, 2 * n + 2) << "seed " << seed;
        EXPECT_EQ(r.graph.elements(), std::size_t(4 * n + 3));
        EXPECT_EQ(firedOf(g, r, "Plant centre"), 1);
        EXPECT_EQ(firedOf(g, r, "Heart"), 1);
        EXPECT_EQ(firedOf(g, r, "Add petal"), n);
        EXPECT_EQ(firedOf(g, r, "Decorate petal"), n);
    }
    EXPECT_GE(seen.size(), 5u) << "the petal count varies with the seed";
}

TEST(ShippedGraphGrammars, RadialPetalTipsAreEvenlySpacedOnACircle) {
    const GraphGrammar g = shipped("radial.yml");
    const double pi = std::acos(-1.0);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        const Vec2 c = r.graph.vertex(0).position;
        std::vector<double> angles;
        for (const HostEdge& e : r.graph.edges()) {
            if (!e.alive || !textAttrIs(g, e.attrs, "kind", "spoke")) continue;
            const Vec2 tip = r.graph.vertex(e.vertex2).position;
            EXPECT_NEAR(std::hypot(tip.x - c.x, tip.y - c.y), 3.0, 1e-9);
            angles.push_back(std::atan2(tip.y - c.y, tip.x - c.x));
        }
        std::sort(angles.begin(), angles.end());
        const double step = 2 * pi / double(angles.size());
        for (std::size_t i = 1; i < angles.size(); ++i) EXPECT_NEAR(angles[i] - angles[i - 1], step, 1e-9) << "seed " << seed;
    }
}

// --- tiled.yml and mosaic.yml: a sheet cut into square tiles ------------------------------------

struct Tile {
    Vec2 lo, hi;
    const HostEdge* edge;  ///< the tile's diagonal edge (kind "tile")
};

/// The tiles of a derived sheet: each edge of kind "tile" spans its tile's diagonal.
std::vector<Tile> tilesOf(const GraphGrammar& g, const HostGraph& graph) {
    std::vector<Tile> tiles;
    for (const HostEdge& e : graph.edges()) {
        if (!e.alive || !textAttrIs(g, e.attrs, "kind", "tile")) continue;
        const Vec2 a = graph.vertex(e.vertex1).position, b = graph.vertex(e.vertex2).position;
        tiles.push_back({{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}, &e});
    }
    return tiles;
}

/// Each tile is square, no two overlap, and together they make up the 8 x 8 sheet.
void expectSquaresMakingUpTheSheet(const std::vector<Tile>& tiles, std::uint64_t seed) {
    double area = 0;
    for (const Tile& t : tiles) {
        EXPECT_NEAR(t.hi.y - t.lo.y, t.hi.x - t.lo.x, 1e-12) << "seed " << seed << ": a tile is square";
        area += (t.hi.x - t.lo.x) * (t.hi.y - t.lo.y);
    }
    EXPECT_NEAR(area, 64.0, 1e-9) << "seed " << seed << ": the tiles make up the 8 x 8 sheet";
    for (std::size_t i = 0; i < tiles.size(); ++i)
        for (std::size_t j = i + 1; j < tiles.size(); ++j) {
            const double w = std::min(tiles[i].hi.x, tiles[j].hi.x) - std::max(tiles[i].lo.x, tiles[j].lo.x);
            const double h = std::min(tiles[i].hi.y, tiles[j].hi.y) - std::max(tiles[i].lo.y, tiles[j].lo.y);
            EXPECT_FALSE(w > 1e-9 && h > 1e-9) << "seed " << seed << ": tiles " << i << " and " << j << " overlap";
        }
}

TEST(ShippedGraphGrammars, TiledTilesCoverTheSheetWithoutOverlapping) {
    const GraphGrammar g = shipped("tiled.yml");
    std::set<std::size_t> counts;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        const std::vector<Tile> tiles = tilesOf(g, r.graph);
        for (const Tile& tile : tiles) {
            const double level = numberAttr(g, tile.edge->attrs, "level");
            EXPECT_NEAR(tile.hi.x - tile.lo.x, 8.0 / std::pow(2.0, level), 1e-12) << "a tile of level L is 8 / 2^L wide";
            EXPECT_LE(level, 3);
        }
        expectSquaresMakingUpTheSheet(tiles, seed);
        // 4 + 3s tiles after s cuts; 8 elements per cut (the sheet's too), 4 per laid tile.
        const std::size_t t = tiles.size();
        ASSERT_EQ((t - 4) % 3, 0u) << "seed " << seed;
        const std::size_t cuts = (t - 4) / 3;
        EXPECT_EQ(r.graph.elements(), 3 + 8 * (1 + cuts) + 4 * t) << "seed " << seed;
        EXPECT_EQ(firedOf(g, r, "Quarter sheet"), 1);
        EXPECT_EQ(firedOf(g, r, "Lay tile"), std::int64_t(t));
        counts.insert(t);
    }
    EXPECT_GE(counts.size(), 5u) << "the tile count varies with the seed";
}

// --- mosaic.yml -------------------------------------------------------------------------------

TEST(ShippedGraphGrammars, MosaicTilesMakeUpTheSheetAndEachHoldsAtMostOneStoneInsideIt) {
    const GraphGrammar g = shipped("mosaic.yml");
    std::set<std::size_t> counts;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        const std::vector<Tile> tiles = tilesOf(g, r.graph);
        for (const Tile& tile : tiles) EXPECT_GE(tile.hi.x - tile.lo.x, 0.5 - 1e-12) << "the smallest tile is 0.5 wide";
        expectSquaresMakingUpTheSheet(tiles, seed);
        // Every stone sits at the centre of its own tile.
        std::size_t stones = 0;
        std::vector<int> used(tiles.size(), 0);
        for (const HostVertex& v : r.graph.vertices()) {
            if (!v.alive || !textAttrIs(g, v.attrs, "role", "stone")) continue;
            ++stones;
            int in = -1;
            for (std::size_t t = 0; t < tiles.size(); ++t)
                if (std::abs(v.position.x - (tiles[t].lo.x + tiles[t].hi.x) / 2) < 1e-9 &&
                    std::abs(v.position.y - (tiles[t].lo.y + tiles[t].hi.y) / 2) < 1e-9)
                    in = int(t);
            ASSERT_GE(in, 0) << "seed " << seed << ": a stone off every tile's centre";
            EXPECT_EQ(++used[std::size_t(in)], 1) << "seed " << seed << ": two stones on one tile";
        }
        const std::size_t t = tiles.size();
        ASSERT_EQ((t - 4) % 3, 0u) << "seed " << seed;
        const std::size_t cuts = (t - 4) / 3;
        EXPECT_EQ(r.graph.elements(), 3 + 8 * (1 + cuts) + 2 * stones) << "seed " << seed;
        EXPECT_EQ(firedOf(g, r, "Lay tile"), std::int64_t(t)) << "every tile is laid once";
        counts.insert(t);
    }
    EXPECT_GE(counts.size(), 5u) << "the tile count varies with the seed";
}

TEST(ShippedGraphGrammars, TiledEveryTileGetsOneGlazeAndOneMotifAtItsCentre) {
    const GraphGrammar g = shipped("tiled.yml");
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        std::multiset<std::pair<double, double>> centres, glazes, motifs;
        for (const HostEdge& e : r.graph.edges())
            if (e.alive && textAttrIs(g, e.attrs, "kind", "tile")) {
                EXPECT_TRUE(attrOf(g, e.attrs, "decorated") && truthy(*attrOf(g, e.attrs, "decorated")));
                const Vec2 a = r.graph.vertex(e.vertex1).position, b = r.graph.vertex(e.vertex2).position;
                centres.insert({(a.x + b.x) / 2, (a.y + b.y) / 2});
            }
        for (const HostVertex& v : r.graph.vertices()) {
            if (!v.alive) continue;
            if (textAttrIs(g, v.attrs, "role", "glaze")) {
                glazes.insert({v.position.x, v.position.y});
                EXPECT_TRUE(textAttrIs(g, v.attrs, ".svg_tag", "rect"));
            }
            if (textAttrIs(g, v.attrs, "role", "motif")) motifs.insert({v.position.x, v.position.y});
        }
        EXPECT_EQ(glazes, centres) << "seed " << seed;
        EXPECT_EQ(motifs, centres) << "seed " << seed;
    }
}

// --- facade.yml -------------------------------------------------------------------------------

struct FacadeParts {
    std::vector<const HostVertex*> floors, windows, doors, blinds;
};

FacadeParts partsOf(const GraphGrammar& g, const HostGraph& graph) {
    FacadeParts parts;
    for (const HostVertex& v : graph.vertices()) {
        if (!v.alive) continue;
        if (hasAttr(g, v.attrs, "placed")) parts.floors.push_back(&v);
        if (hasAttr(g, v.attrs, "window")) parts.windows.push_back(&v);
        if (hasAttr(g, v.attrs, "is_door")) parts.doors.push_back(&v);
        if (hasAttr(g, v.attrs, "blind")) parts.blinds.push_back(&v);
    }
    return parts;
}

TEST(ShippedGraphGrammars, FacadeHasFloorsTimesWindowsPerFloorWindowsAndExactlyOneDoor) {
    const GraphGrammar g = shipped("facade.yml");
    std::set<std::pair<int, int>> shapes;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        EXPECT_EQ(r.stop, DeriveResult::Stop::Terminal);
        const AttrMap& building = r.graph.vertex(0).attrs;
        const int floors = int(numberAttr(g, building, "floors")), perFloor = int(numberAttr(g, building, "per_floor"));
        shapes.insert({floors, perFloor});
        const FacadeParts parts = partsOf(g, r.graph);
        EXPECT_EQ(parts.floors.size(), std::size_t(floors)) << "seed " << seed;
        EXPECT_EQ(parts.windows.size(), std::size_t(floors * perFloor)) << "seed " << seed;
        ASSERT_EQ(parts.doors.size(), 1u) << "seed " << seed;
        EXPECT_LT(parts.doors[0]->position.y, 3.0) << "the door is on the ground floor";
        for (const HostVertex* w : parts.windows)  // no window in the door's bay on the ground floor
            EXPECT_FALSE(w->position.y < 3.0 && std::abs(w->position.x - parts.doors[0]->position.x) < 1.25) << "seed " << seed;
        EXPECT_EQ(r.steps, 2 + floors + 2 * floors * perFloor) << "seed " << seed;
        EXPECT_EQ(r.graph.elements(), std::size_t(7 + 2 * floors + 4 * floors * perFloor)) << "seed " << seed;
    }
    EXPECT_GE(shapes.size(), 6u) << "floors and windows per floor vary with the seed";
}

TEST(ShippedGraphGrammars, FacadeHangsExactlyOneBlindInEachWindow) {
    const GraphGrammar g = shipped("facade.yml");
    int open = 0, lowered = 0;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const DeriveResult r = deriveSeeded(g, seed);
        const HostGraph& graph = r.graph;
        const FacadeParts parts = partsOf(g, graph);
        EXPECT_EQ(parts.blinds.size(), parts.windows.size());
        for (const HostVertex* w : parts.windows) {
            int blinds = 0;
            for (ElementId e : w->edges) {
                const HostEdge& edge = graph.edge(e);
                const ElementId other = &graph.vertex(edge.vertex1) == w ? edge.vertex2 : edge.vertex1;
                const HostVertex& b = graph.vertex(other);
                if (!hasAttr(g, b.attrs, "blind")) continue;
                ++blinds;
                EXPECT_NEAR(b.position.x, w->position.x, 1e-9) << "a blind hangs in its window";
                EXPECT_GE(b.position.y, w->position.y - 0.85);
                EXPECT_LE(b.position.y, w->position.y + 0.85);
                const double drop = numberAttr(g, b.attrs, "drop");
                if (textAttrIs(g, b.attrs, "blind", "open")) {
                    ++open;
                    EXPECT_EQ(drop, 0.0);
                } else {
                    ++lowered;
                    EXPECT_TRUE(drop >= 0.25 && drop <= 0.9) << drop;
                }
            }
            EXPECT_EQ(blinds, 1) << "seed " << seed;
        }
    }
    EXPECT_GT(open, 0) << "both weighted options occur";
    EXPECT_GT(lowered, open) << "lowered blinds weigh 3, open ones 2";
}

}  // namespace shipped_graph_grammars_test
