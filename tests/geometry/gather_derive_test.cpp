// send / gather (PCGR's collective operations, grammars/README.md "Lists"): every step and route
// against a brute-force reference on random genomes (the same model written without the gather
// emits each entity, and the reference applies the step to those boxes); execution scopes (an
// invocation's gather sees exactly what that invocation sent: PCGR's Fig. 9, one door per street
// or per house); gathers chained within one body; routed entities' piece.index / piece.count;
// the memo (incremental derivation) gives the same bits; a list past its limit truncates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "../geometry_compare.hpp"
#include "gather_test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {

using namespace gather_test;

TEST(Gather, OrderByDescendingThenKeepFirstKIsTheKTallestInOrder) {
    forRandomGenomes("    order by scope.size.y desc", "    keep first k : { box } | rest : nil", 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto& out, int seed) {
                         std::vector<Primitive> expected = sortedBy(all, {{height, true}});
                         expected.resize(std::min<std::size_t>(expected.size(), std::size_t(param(g, c, 1))));
                         expectBoxes(expected, out, seed);
                     });
}

TEST(Gather, OrderByTwoKeysIsStableAndEachKeyHasItsDirection) {
    forRandomGenomes("    order by scope.size.z asc, scope.origin.x desc", "    each : { box }", 300,
                     [](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         expectBoxes(sortedBy(all, {{depth, false}, {x, true}}), out, seed);
                     });
    forRandomGenomes("    order by scope.size.z", "    each : { box }", 100,  // ties keep the derivation's order
                     [](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         expectBoxes(sortedBy(all, {{depth, false}}), out, seed);
                     });
}

TEST(Gather, KeepFirstFromSkipsAndRestTakesTheOthersInListOrder) {
    forRandomGenomes("", "    keep first k from 2 : { box } | rest : { translate (0, 100, 0) box }", 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto& out, int seed) {
                         const std::size_t k = std::size_t(param(g, c, 1)), n = all.size();
                         std::vector<Primitive> expected;
                         for (std::size_t i = 2; i < std::min(n, 2 + k); ++i) expected.push_back(all[i]);
                         for (std::size_t i = 0; i < n; ++i)
                             if (i < 2 || i >= 2 + k) {
                                 Primitive p = all[i];
                                 p.centre.y += 100.0f;
                                 expected.push_back(p);
                             }
                         expectBoxes(expected, out, seed);
                     });
}

TEST(Gather, ReverseThenWhereRoutesByTheConditionPerEntity) {
    forRandomGenomes("    reverse", "    where (scope.size.y > t) : { box } | else : { translate (0, 0, 50) box }", 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto& out, int seed) {
                         const float t = param(g, c, 2);
                         std::vector<Primitive> yes, no;
                         for (std::size_t i = all.size(); i-- > 0;) {
                             if (height(all[i]) > t) {
                                 yes.push_back(all[i]);
                             } else {
                                 Primitive p = all[i];
                                 p.centre.z += 50.0f;
                                 no.push_back(p);
                             }
                         }
                         yes.insert(yes.end(), no.begin(), no.end());
                         expectBoxes(yes, out, seed);
                     });
}

TEST(Gather, AggregatesAreComputedLeftToRightOverTheList) {
    forRandomGenomes("    let lo = min(scope.size.y)\n    let hi = max(scope.size.y)\n    let mean = avg(scope.size.y)\n"
                     "    let total = sum(scope.size.z)\n    let centre = avg(scope.origin)",
                     "    each : { size (hi - lo, mean, total) translate (centre.x, 0, 0) box }", 300,
                     [](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         ASSERT_EQ(out.size(), all.size()) << seed;
                         if (all.empty()) return;
                         double lo = height(all[0]), hi = lo, sumY = 0, sumZ = 0, sumX = 0;
                         for (const Primitive& p : all) {
                             lo = std::min<double>(lo, height(p));
                             hi = std::max<double>(hi, height(p));
                             sumY += height(p);
                             sumZ += depth(p);
                             sumX += p.centre.x;
                         }
                         const float spread = float(hi) - float(lo), mean = float(sumY / double(all.size()));
                         for (std::size_t i = 0; i < out.size(); ++i) {
                             EXPECT_EQ(out[i].half.x, std::fabs(spread) * 0.5f) << seed;
                             EXPECT_EQ(out[i].half.y, mean * 0.5f) << seed;
                             EXPECT_EQ(out[i].half.z, float(sumZ) * 0.5f) << seed;
                             EXPECT_NEAR(out[i].centre.x, all[i].centre.x + float(sumX / double(all.size())), 1e-3) << seed;
                         }
                     });
}

TEST(Gather, ShuffleIsAPermutationDrawnFromItsParameter) {
    std::set<std::vector<float>> orders;
    forRandomGenomes("    shuffle u", "    each : { box }", 200,
                     [&](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         ASSERT_EQ(out.size(), all.size());
                         std::vector<float> a, b;
                         for (const Primitive& p : all) a.push_back(p.centre.x);
                         for (const Primitive& p : out) b.push_back(p.centre.x);
                         EXPECT_TRUE(std::is_permutation(a.begin(), a.end(), b.begin())) << seed;
                         if (all.size() >= 5) orders.insert(b);
                     });
    EXPECT_GT(orders.size(), 100u);  // the orders differ between genomes
}

TEST(Gather, RoutedEntitiesReadTheirPlaceAmongThoseRoutedTheSameWay) {
    const Grammar g = parseGrammar(
        items("send items", "  gather items {\n    keep first 3 : { color (piece.index / 100, piece.count / 100, 0) box } | rest : nil\n  }\n"),
        "places.grammar");
    for (int seed = 1; seed <= 50; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const Geometry geo = deriveOne(g, c);
        for (std::size_t i = 0; i < geo.primitives.size(); ++i) {
            EXPECT_EQ(geo.appearance[i].color[0], float(i) / 100.0f);
            EXPECT_EQ(geo.appearance[i].color[1], float(geo.primitives.size()) / 100.0f);
        }
    }
}

namespace gather_derive_test {
/// PCGR's Fig. 9: houses along a street, each with facades; one door goes on the smallest facade.
/// WHERE says where the gather is: in the street (one door), in each house (one per house), or
/// in each house reached as a gene of its own through `child`; or "nested": in each house, whose
/// route sends the chosen facade on to the street's own gather of `facades`, which places the door.
std::string street(const std::string& where) {
    const bool inStreet = where == "street", asChild = where == "child", nested = where == "nested";
    const std::string door = std::string("  gather facades {\n    order by scope.size.x * scope.size.y\n    keep first 1 : ") +
                             (nested ? "{ send facades }" : "Door") + " | rest : nil\n  }\n";
    return std::string("start Street\n") +
           "rule Street {\n  size (40, 1, 10)\n  repeat x count 4 " + (asChild ? "{ child House }" : "House") + "\n" +
           (inStreet ? door : "") + (nested ? "  gather facades {\n    each : Door\n  }\n" : "") + "}\n" +
           "rule House {\n  param w = uniform(0.5, 0.8) per piece\n  param h = uniform(3, 8) per piece\n"
           "  size (scope.size.x * w, h, 6 + 3 * w)\n  box\n  comp { side: { send facades } }\n" +
           (inStreet ? "" : door) + "}\n" +
           "rule Door {\n  color (1, 0, 0)\n  extrude 0.2\n  size (1, 2, 0.2)\n  box\n}\n";
}
std::vector<Primitive> doors(const Geometry& geo) {
    std::vector<Primitive> out;
    for (std::size_t i = 0; i < geo.primitives.size(); ++i)
        if (geo.appearance[i].color[0] == 1.0f) out.push_back(geo.primitives[i]);
    return out;
}
}  // namespace gather_derive_test

using namespace gather_derive_test;

TEST(Gather, ExecutionScopesGiveOneDoorPerStreetOrOnePerHouseOnTheSameFacades) {
    const Grammar inStreet = parseGrammar(street("street"), "street.grammar");
    const Grammar inHouse = parseGrammar(street("house"), "house.grammar");
    const Grammar asChild = parseGrammar(street("child"), "child.grammar");
    for (int seed = 1; seed <= 30; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(inHouse, c, rng, 10));
        const std::vector<Primitive> one = doors(deriveOne(inStreet, c)), perHouse = doors(deriveOne(inHouse, c));
        EXPECT_EQ(one.size(), 1u) << seed;
        ASSERT_EQ(perHouse.size(), 4u) << seed;
        std::set<float> housesWithADoor;
        for (const Primitive& d : perHouse) housesWithADoor.insert(std::round((d.centre.x + 15.0f) / 10.0f));  // houses 0.5-0.8 of a 10-unit lot: a door is within 4.5 of its centre
        EXPECT_EQ(housesWithADoor.size(), 4u) << "one door in each house, seed " << seed;
        EXPECT_TRUE(std::any_of(perHouse.begin(), perHouse.end(), [&](const Primitive& p) { return sameBox(p, one[0]); }))
            << "the street's door is one of the houses' doors, seed " << seed;
        Chromosome g;
        Rng rng2{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(asChild, g, rng2, 10));
        EXPECT_EQ(doors(deriveOne(asChild, g)).size(), 4u) << seed;
    }
}

TEST(Gather, ASendGoesToTheInnermostOpenGatherOfItsList) {
    // Street and House both gather `facades`: a house's sides go to the house's own gather, whose
    // route sends its smallest side on to the street's (the house's is closed for its routes).
    const Grammar nested = parseGrammar(street("nested"), "nested.grammar");
    const Grammar inHouse = parseGrammar(street("house"), "house.grammar");
    for (int seed = 1; seed <= 30; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(inHouse, c, rng, 10));
        const std::vector<Primitive> expected = doors(deriveOne(inHouse, c)), got = doors(deriveOne(nested, c));
        expectBoxes(expected, got, seed);
    }
}

TEST(Gather, ARouteMaySendToALaterGatherOfTheSameBody) {
    const Grammar g = parseGrammar(items("send first",
                                         "  gather first {\n    order by scope.size.y desc\n    keep first k : { send second } | rest : nil\n  }\n"
                                         "  gather second {\n    order by scope.origin.x\n    each : { box }\n  }\n"),
                                   "chain.grammar");
    const Grammar reference = parseGrammar(items("box", ""), "reference.grammar");
    for (int seed = 1; seed <= 100; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        std::vector<Primitive> expected = sortedBy(deriveOne(reference, c).primitives, {{height, true}});
        expected.resize(std::min<std::size_t>(expected.size(), std::size_t(param(g, c, 1))));
        expectBoxes(sortedBy(expected, {{x, false}}), deriveOne(g, c).primitives, seed);
    }
}

TEST(Gather, TheMemoGivesTheSameBitsAsAFreshDerivation) {
    const Grammar g = parseGrammar(street("child"), "child.grammar");
    DeriveScratch withMemo;
    withMemo.memo = std::make_unique<SubtreeMemo>(1u << 20);
    for (int seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        for (int again = 0; again < 2; ++again) {  // the second time, the houses come from the memo
            Geometry geo;
            ASSERT_EQ(derive(g, c, geo, withMemo), DeriveStatus::Complete);
            EXPECT_TRUE(test::identical(geo, deriveOne(g, c))) << seed;
        }
    }
}

TEST(Gather, AListPastItsLimitTruncatesTheDerivation) {
    const Grammar g = parseGrammar("start S\nrule S {\n  repeat x count 300 { repeat z count 300 { send all } }\n"
                                   "  gather all {\n    keep first 1 : { box } | rest : nil\n  }\n}\n",
                                   "many.grammar");
    Chromosome c;
    Rng rng(1);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch, 1000000), DeriveStatus::Truncated);
    const Grammar fewer = parseGrammar("start S\nrule S {\n  repeat x count 200 { repeat z count 200 { send all } }\n"
                                       "  gather all {\n    keep first 1 : { box } | rest : nil\n  }\n}\n",
                                       "fewer.grammar");
    Chromosome f;
    ASSERT_TRUE(growUncontrolled(fewer, f, rng, 10));
    EXPECT_EQ(derive(fewer, f, geo, scratch, 1000000), DeriveStatus::Complete);
    EXPECT_EQ(geo.primitives.size(), 1u);
}

}  // namespace shapevo
