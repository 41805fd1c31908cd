// Collective nodes in `.pcg` graphs (PCGR's square ports) derive what send / gather say: PCGR's
// Fig. 9 as graphs (grammars/pcg/street.pcg with house.pcg) derives bit for bit the street written
// by hand (street.grammar) and gives one door per house, while street-one-door.pcg, the same
// collective nodes in the street's own graph, gives one door for the whole street, on one of those
// facades; every collective node (order_by, reverse, shuffle, amount_filter, filter), a chain of
// them and a route into another collective node derive bit for bit their hand-written gathers
// (a gather that a route sends to runs after the gather of that route).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/pcg/pcg_front_end.hpp"

namespace shapevo {
namespace pcg_collective_derive_test_helpers {

using test::sourcePath;

using test::deriveComplete;

/// door.pcg's colour: every door slab.
std::vector<Primitive> doors(const Geometry& geo) {
    std::vector<Primitive> out;
    for (std::size_t i = 0; i < geo.primitives.size(); ++i)
        if (geo.appearance[i].color[0] == 0.7f && geo.appearance[i].color[1] == 0.1f) out.push_back(geo.primitives[i]);
    return out;
}

/// Which of street.pcg's four lots (x from -22: widths 9, 13, 10, 12) a point is on.
int lotOf(float x) { return x < -13.0f ? 0 : x < 0.0f ? 1 : x < 10.0f ? 2 : 3; }

// Every collective node: six boxes of heights 1..6 sent to `tall` (order by height, tallest
// first), reversed, shuffled; then entities 1 and 2 turn red, the rest go on to `thin`, a second
// gather, whose `where` routes them to spheres or cones.
constexpr const char* kEveryNode = R"(graph Lists
param u = uniform(0, 1)
in start : volume
node row   = size(12, 1, 2)
node cut   = repeat(x, count: 6)
node grow  = size(y: 1 + piece.index)
node tall  = order_by(scope.size.y desc, scope.origin.x)
node back  = reverse()
node mix   = shuffle(u)
node two   = amount_filter(count: 2, from: 1)
node red   = color(1, 0, 0)
node brick = box()
node thin  = filter(scope.size.y > 3)
node ball  = sphere()
node cone  = cone()
node last  = order_by(scope.origin.x)
node grey  = color(0.5, 0.5, 0.5)
node cube  = box()
start      -> row
row        -> cut
cut.piece  -> grow
grow       -> tall, last
tall       -> back
back       -> mix
mix        -> two
two.first  -> red
red        -> brick
two.rest   -> thin
thin.true  -> ball
thin.false -> cone
last       -> grey
grey       -> cube
)";

constexpr const char* kEveryNodeByHand = R"(start Lists
rule Lists {
  param u = uniform(0, 1)
  size (12, 1, 2)
  repeat x count 6 {
    size (scope.size.x, 1 + piece.index, scope.size.z)
    [ send tall ]
    [ send last ]
  }
  gather tall {
    order by scope.size.y desc, scope.origin.x
    reverse
    shuffle u
    keep first 2 from 1 : { color (1, 0, 0) box } | rest : { send thin }
  }
  gather thin {
    where (scope.size.y > 3) : { sphere } | else : { cone }
  }
  gather last {
    order by scope.origin.x
    each : { color (0.5, 0.5, 0.5) box }
  }
}
)";

// The grouping nodes: group_by with two aggregates (a count and the group's number) and an
// amount filter per group; cluster then merge; unify then ungroup.
constexpr const char* kGroupingNodes = R"(graph Groups
param k = int(1, 4)
in start : volume
node row   = size(12, 1, 2)
node cut   = repeat(x, count: 6)
node grow  = size(y: 1 + piece.index - 2 * floor(piece.index / 2))
node same  = group_by(scope.size.y)
node count = aggregate(name: n, kind: sum, value: 1)
node num   = aggregate(name: gi, kind: group_index)
node two   = amount_filter(count: 2)
node mark  = color(gi, n / 10, 0)
node brick = box()
node near  = cluster(k: k, by: scope.origin)
node whole = merge()
node slab  = box()
node flat  = unify(within: 0.01)
node again = ungroup()
node cube  = box()
start      -> row
row        -> cut
cut.piece  -> grow
grow       -> same, near, flat
same       -> count
count      -> num
num        -> two
two.first  -> mark
mark       -> brick
near       -> whole
whole      -> slab
flat       -> again
again      -> cube
)";

constexpr const char* kGroupingNodesByHand = R"(start Groups
rule Groups {
  param k = int(1, 4)
  size (12, 1, 2)
  repeat x count 6 {
    size (scope.size.x, 1 + piece.index - 2 * floor(piece.index / 2), scope.size.z)
    [ send same ]
    [ send near ]
    [ send flat ]
  }
  gather same {
    group by scope.size.y
    let n = sum(1)
    let gi = group.index
    keep first 2 : { color (gi, n / 10, 0) box } | rest : nil
  }
  gather near {
    cluster k by scope.origin
    merge
    each : { box }
  }
  gather flat {
    unify within 0.01
    ungroup
    each : { box }
  }
}
)";

}  // namespace pcg_collective_derive_test_helpers

using namespace pcg_collective_derive_test_helpers;

TEST(PcgCollective, TheFig9StreetGraphDerivesBitIdenticallyToTheHandWrittenStreet) {
    const Grammar graph = loadGrammar(sourcePath("grammars/pcg/street.pcg"));
    const Grammar hand = loadGrammar(sourcePath("grammars/pcg/street.grammar"));
    ASSERT_EQ(graph.rules[graph.start].geneWords(), hand.rules[hand.start].geneWords());
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(graph, c, rng, 100));
        const Geometry a = deriveComplete(graph, c), b = deriveComplete(hand, c);
        EXPECT_EQ(doors(a).size(), 4u) << "seed " << seed;
        EXPECT_TRUE(test::identical(a, b)) << "seed " << seed;
    }
}

TEST(PcgCollective, CollectiveNodesInTheHouseGraphGiveOneDoorPerHouseAndInTheStreetGraphOneDoorOnOneOfThoseFacades) {
    const Grammar perHouse = loadGrammar(sourcePath("grammars/pcg/street.pcg"));
    const Grammar inStreet = loadGrammar(sourcePath("grammars/pcg/street-one-door.pcg"));
    ASSERT_EQ(perHouse.rules[perHouse.start].geneWords(), inStreet.rules[inStreet.start].geneWords());
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(perHouse, c, rng, 100));
        const std::vector<Primitive> each = doors(deriveComplete(perHouse, c)), one = doors(deriveComplete(inStreet, c));
        std::set<int> lots;
        for (const Primitive& d : each) lots.insert(lotOf(d.centre.x));
        EXPECT_EQ(lots.size(), 4u) << "one door on each house, seed " << seed;
        ASSERT_EQ(one.size(), 1u) << "one door in the whole street, seed " << seed;
        bool among = false;
        for (const Primitive& d : each) among = among || (d.centre == one[0].centre && d.axes == one[0].axes);
        EXPECT_TRUE(among) << "the street's door is on the facade one house chose, seed " << seed;
    }
}

TEST(PcgCollective, TheIncludedGraphsGathersGoIntoARuleRunPerEntityAndTheStreetsIntoTheGraphRule) {
    for (const char* file : {"grammars/pcg/street.pcg", "grammars/pcg/street-one-door.pcg"}) {
        const std::string path = sourcePath(file);
        const std::string text = pcg::translatePcg(test::readFile(path), path).text;
        const bool perHouse = std::string(file).find("one-door") == std::string::npos;
        const std::string list = perHouse ? "pcg_l_house__area" : "pcg_l_area";
        EXPECT_NE(text.find("send " + list + "\n"), std::string::npos) << text;
        const std::size_t rule = text.find(perHouse ? "rule pcg_s_house__lot(house__depth) {" : "rule StreetOneDoor {");
        const std::size_t gather = text.find("gather " + list + " {\n    order by scope.size.x * scope.size.y\n    keep first 1 : {");
        ASSERT_NE(rule, std::string::npos) << text;
        ASSERT_NE(gather, std::string::npos) << text;
        EXPECT_LT(rule, gather);
        EXPECT_EQ(text.find("rule ", rule + 1) == std::string::npos || text.find("rule ", rule + 1) > gather, true)
            << "the gather is in that rule:\n" << text;
    }
}

TEST(PcgCollective, EveryCollectiveNodeAChainAndARouteIntoAnotherListDeriveTheirHandWrittenGathers) {
    test::TempDir dir;
    test::writeFile(dir.file("lists.pcg"), kEveryNode);
    test::writeFile(dir.file("lists.grammar"), kEveryNodeByHand);
    const Grammar graph = loadGrammar(dir.file("lists.pcg"));
    const Grammar hand = loadGrammar(dir.file("lists.grammar"));
    ASSERT_EQ(graph.rules[graph.start].geneWords(), hand.rules[hand.start].geneWords());
    std::set<float> redHeights;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(graph, c, rng, 10));
        const Geometry a = deriveComplete(graph, c), b = deriveComplete(hand, c);
        EXPECT_TRUE(test::identical(a, b)) << "seed " << seed;
        std::size_t red = 0, spheres = 0, cones = 0;
        for (std::size_t i = 0; i < a.primitives.size(); ++i) {
            red += a.appearance[i].color[0] == 1.0f;
            if (a.appearance[i].color[0] == 1.0f) redHeights.insert(a.primitives[i].half.y * 2.0f);
            spheres += a.primitives[i].kind == PrimitiveKind::Sphere;
            cones += a.primitives[i].kind == PrimitiveKind::Cone;
        }
        EXPECT_EQ(red, 2u) << "keep first 2 from 1, seed " << seed;
        EXPECT_EQ(spheres + cones, 4u) << "the rest, routed by the second gather, seed " << seed;
        EXPECT_EQ(a.primitives.size(), 12u) << "six red or routed, six grey";
    }
    EXPECT_GT(redHeights.size(), 2u) << "the shuffle draws different boxes for different genomes";
}

TEST(PcgCollective, TheGroupingNodesDeriveTheirHandWrittenGathers) {
    test::TempDir dir;
    test::writeFile(dir.file("groups.pcg"), kGroupingNodes);
    test::writeFile(dir.file("groups.grammar"), kGroupingNodesByHand);
    const Grammar graph = loadGrammar(dir.file("groups.pcg"));
    const Grammar hand = loadGrammar(dir.file("groups.grammar"));
    ASSERT_EQ(graph.rules[graph.start].geneWords(), hand.rules[hand.start].geneWords());
    std::set<std::size_t> merged;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(graph, c, rng, 10));
        const Geometry a = deriveComplete(graph, c), b = deriveComplete(hand, c);
        EXPECT_TRUE(test::identical(a, b)) << "seed " << seed;
        std::size_t marked = 0;
        for (std::size_t i = 0; i < a.primitives.size(); ++i) {
            if (a.appearance[i].color[1] != 0.3f) continue;  // n / 10: three boxes in each group
            EXPECT_EQ(a.appearance[i].color[0], float(marked / 2)) << "group.index, seed " << seed;
            ++marked;
        }
        EXPECT_EQ(marked, 4u) << "two of each group of three, seed " << seed;
        merged.insert(a.primitives.size() - 4 - 6);  // one box per cluster
    }
    EXPECT_GT(merged.size(), 1u) << "k is evolved";
}

TEST(PcgCollective, AChanceBeforeAnIncludedGraphWithCollectiveNodesRunsItsGatherInTheNewGene) {
    test::TempDir dir;
    test::writeFile(dir.file("row.pcg"), "graph Row\nin lot : volume\nnode cut = repeat(x, count: 3)\nnode o = reverse()\n"
                                         "node b = box()\nlot -> cut\ncut.piece -> o\no -> b\n");
    test::writeFile(dir.file("main.pcg"), "graph Main\nin start : volume\nnode c = chance(0.9)\nnode r = include \"row.pcg\"\n"
                                          "start -> c\nc.yes -> r\n");
    const Grammar g = loadGrammar(dir.file("main.pcg"));  // no "send with no gather"
    std::size_t withRow = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const std::size_t boxes = deriveComplete(g, c).primitives.size();
        EXPECT_TRUE(boxes == 0 || boxes == 3) << seed;
        withRow += boxes == 3;
    }
    EXPECT_GT(withRow, 0u);
}

}  // namespace shapevo
