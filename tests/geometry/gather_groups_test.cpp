// The grouping steps of a gather (grammars/README.md "Groups"): group by, cluster (k-means),
// unify and merge, ungroup, and what the other steps and the routes do within groups (order,
// shuffle, let, keep first, piece.index / piece.count), each against a brute-force reference on
// random genomes: the same model written without the gather emits every entity, and the
// reference groups those boxes itself (a literal Lloyd iteration for cluster, runs of touching
// boxes for unify).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "gather_test_support.hpp"

namespace shapevo {
namespace gather_groups_test {

using gather_test::depth;
using gather_test::height;

/// Positions of `boxes` grouped by `key` (exact equality): groups in order of first appearance,
/// members in list order.
template <class Key>
std::vector<std::vector<std::size_t>> groupsBy(const std::vector<Primitive>& boxes, Key key) {
    std::vector<std::vector<std::size_t>> groups;
    std::vector<float> keys;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto at = std::find(keys.begin(), keys.end(), key(boxes[i]));
        if (at == keys.end()) {
            keys.push_back(key(boxes[i]));
            groups.push_back({i});
        } else {
            groups[std::size_t(at - keys.begin())].push_back(i);
        }
    }
    return groups;
}

/// Lloyd's k-means, literally: the first K points start as centroids; assign each point to the
/// nearest (ties to the lowest index); stop when no point changes; move each centroid to its
/// members' mean. The labels of the last assignment.
std::vector<std::uint32_t> lloyd(const std::vector<glm::dvec3>& points, std::uint32_t k) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> label(n, UINT32_MAX);
    if (n == 0) return label;
    const std::size_t clusters = std::min<std::size_t>(std::max<std::uint32_t>(k, 1), n);
    std::vector<glm::dvec3> centroid(points.begin(), points.begin() + std::ptrdiff_t(clusters));
    for (int round = 0; round < 100; ++round) {
        bool changed = false;
        for (std::size_t i = 0; i < n; ++i) {
            std::uint32_t best = 0;
            for (std::uint32_t c = 1; c < clusters; ++c) {
                const glm::dvec3 a = points[i] - centroid[c], b = points[i] - centroid[best];
                if (glm::dot(a, a) < glm::dot(b, b)) best = c;
            }
            changed |= label[i] != best;
            label[i] = best;
        }
        if (!changed) break;
        for (std::uint32_t c = 0; c < clusters; ++c) {
            glm::dvec3 sum(0.0);
            std::size_t count = 0;
            for (std::size_t i = 0; i < n; ++i)
                if (label[i] == c) {
                    sum += points[i];
                    ++count;
                }
            if (count > 0) centroid[c] = sum / double(count);
        }
    }
    return label;
}

/// The boxes at `groups`' positions, group after group.
std::vector<Primitive> flatten(const std::vector<Primitive>& boxes, const std::vector<std::vector<std::size_t>>& groups) {
    std::vector<Primitive> out;
    for (const auto& group : groups)
        for (std::size_t i : group) out.push_back(boxes[i]);
    return out;
}

/// A route that colours each box with its piece.index and piece.count (over 1000).
constexpr const char* kPlaceRoute = "    each : { color (piece.index / 1000, piece.count / 1000, 0) box }";

/// The derived boxes with their colours, against the expected groups: the same boxes in group
/// order, each coloured with its place in its group.
void expectGroupsWithPlaces(const Grammar& g, const Chromosome& c, const std::vector<Primitive>& all,
                            const std::vector<std::vector<std::size_t>>& groups, int seed) {
    const Geometry geo = gather_test::deriveOne(g, c);
    gather_test::expectBoxes(flatten(all, groups), geo.primitives, seed);
    std::size_t at = 0;
    for (const auto& group : groups)
        for (std::size_t k = 0; k < group.size() && at < geo.appearance.size(); ++k, ++at) {
            EXPECT_EQ(geo.appearance[at].color[0], float(k) / 1000.0f) << "seed " << seed;
            EXPECT_EQ(geo.appearance[at].color[1], float(group.size()) / 1000.0f) << "seed " << seed;
        }
}

}  // namespace gather_groups_test

using namespace gather_groups_test;
using gather_test::forRandomGenomes;

TEST(GatherGroups, GroupByMakesEachGroupContiguousInOrderOfFirstAppearanceAndNumbersWithinIt) {
    forRandomGenomes("    group by scope.size.z", kPlaceRoute, 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto&, int seed) {
                         expectGroupsWithPlaces(g, c, all, groupsBy(all, depth), seed);
                     });
}

TEST(GatherGroups, GroupIndexNumbersTheGroupsInOrder) {
    forRandomGenomes("    group by scope.size.z\n    let gi = group.index", "    each : { color (gi / 1000, 0, 0) box }", 100,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto&, int seed) {
                         const auto groups = groupsBy(all, depth);
                         const Geometry geo = gather_test::deriveOne(g, c);
                         ASSERT_EQ(geo.appearance.size(), all.size()) << seed;
                         std::size_t at = 0;
                         for (std::size_t k = 0; k < groups.size(); ++k)
                             for (std::size_t m = 0; m < groups[k].size(); ++m, ++at)
                                 EXPECT_EQ(geo.appearance[at].color[0], float(k) / 1000.0f) << seed;
                     });
}

TEST(GatherGroups, OrderByAndKeepFirstWorkWithinEachGroup) {
    forRandomGenomes("    group by scope.size.z\n    order by scope.size.y desc", "    keep first k from 1 : { box } | rest : nil", 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto& out, int seed) {
                         const std::size_t k = std::size_t(gather_test::param(g, c, 1));
                         std::vector<Primitive> expected;
                         for (const auto& group : groupsBy(all, depth)) {
                             std::vector<Primitive> members;
                             for (std::size_t i : group) members.push_back(all[i]);
                             members = gather_test::sortedBy(members, {{height, true}});
                             for (std::size_t i = 1; i < members.size() && i < 1 + k; ++i) expected.push_back(members[i]);
                         }
                         gather_test::expectBoxes(expected, out, seed);
                     });
}

TEST(GatherGroups, ALetAfterGroupByIsEachGroupsOwnValue) {
    forRandomGenomes("    group by scope.size.z\n    let top = max(scope.size.y)\n    let n = sum(1)",
                     "    each : { size (n, top, scope.size.z) box }", 300,
                     [](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         const auto groups = groupsBy(all, depth);
                         ASSERT_EQ(out.size(), all.size()) << seed;
                         std::size_t at = 0;
                         for (const auto& group : groups) {
                             float top = 0.0f;
                             for (std::size_t i : group) top = std::max(top, height(all[i]));
                             for (std::size_t k = 0; k < group.size(); ++k, ++at) {
                                 EXPECT_EQ(out[at].half.y, top * 0.5f) << seed;
                                 EXPECT_EQ(out[at].half.x, float(group.size()) * 0.5f) << seed;
                                 EXPECT_EQ(out[at].half.z, all[group[k]].half.z) << seed;
                             }
                         }
                     });
}

TEST(GatherGroups, ShuffleWithinGroupsPermutesEachGroupAndKeepsTheGroupsOrder) {
    forRandomGenomes("    group by scope.size.z\n    shuffle u", "    each : { box }", 200,
                     [](const Grammar&, const Chromosome&, const auto& all, const auto& out, int seed) {
                         ASSERT_EQ(out.size(), all.size()) << seed;
                         std::size_t at = 0;
                         for (const auto& group : groupsBy(all, depth)) {
                             std::vector<float> expected, got;
                             for (std::size_t i : group) expected.push_back(all[i].centre.x);
                             for (std::size_t k = 0; k < group.size(); ++k) got.push_back(out[at++].centre.x);
                             EXPECT_TRUE(std::is_permutation(expected.begin(), expected.end(), got.begin())) << seed;
                         }
                     });
}

TEST(GatherGroups, UngroupKeepsTheGroupsOrderAndRoutesOverTheWholeList) {
    forRandomGenomes("    group by scope.size.z\n    order by scope.size.y\n    ungroup", "    keep first k : { box } | rest : nil", 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto& out, int seed) {
                         std::vector<Primitive> expected;
                         for (const auto& group : groupsBy(all, depth)) {
                             std::vector<Primitive> members;
                             for (std::size_t i : group) members.push_back(all[i]);
                             for (const Primitive& p : gather_test::sortedBy(members, {{height, false}})) expected.push_back(p);
                         }
                         expected.resize(std::min<std::size_t>(expected.size(), std::size_t(gather_test::param(g, c, 1))));
                         gather_test::expectBoxes(expected, out, seed);
                     });
}

TEST(GatherGroups, ClusterGroupsAsLloydsKMeansDoes) {
    forRandomGenomes("    cluster k by scope.origin", kPlaceRoute, 300,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto&, int seed) {
                         std::vector<glm::dvec3> points;
                         for (const Primitive& p : all) points.emplace_back(p.centre);
                         const std::vector<std::uint32_t> label = lloyd(points, std::uint32_t(gather_test::param(g, c, 1)));
                         std::vector<Primitive> labelled = all;
                         for (std::size_t i = 0; i < all.size(); ++i) labelled[i].centre.x = float(label[i]);  // only the key
                         std::vector<std::vector<std::size_t>> groups = groupsBy(labelled, [](const Primitive& p) { return p.centre.x; });
                         expectGroupsWithPlaces(g, c, all, groups, seed);
                     });
}

TEST(GatherGroups, ClusterOnAScalarClustersAlongOneAxis) {
    forRandomGenomes("    cluster 3 by scope.size.y", kPlaceRoute, 200,
                     [](const Grammar& g, const Chromosome& c, const auto& all, const auto&, int seed) {
                         std::vector<glm::dvec3> points;
                         for (const Primitive& p : all) points.emplace_back(double(height(p)), 0.0, 0.0);
                         const std::vector<std::uint32_t> label = lloyd(points, 3);
                         std::vector<Primitive> labelled = all;
                         for (std::size_t i = 0; i < all.size(); ++i) labelled[i].centre.x = float(label[i]);
                         expectGroupsWithPlaces(g, c, all, groupsBy(labelled, [](const Primitive& p) { return p.centre.x; }), seed);
                     });
}

namespace gather_groups_test {
/// n boxes side by side; a box with gap = 1 is half as wide (from its lower x end), so it does
/// not touch the next one. STEPS run on the sent boxes before `each : { box }`.
std::string tiles(const std::string& item, const std::string& steps) {
    return "start S\nrule S {\n  param n = int(0, 24)\n  size (30, 1, 1)\n  repeat x count n Item\n" +
           (steps.empty() ? std::string() : "  gather items {\n" + steps + "\n    each : { box }\n  }\n") +
           "}\nrule Item {\n  param h = uniform(0.1, 5) per piece\n  param gap = int(0, 1) per piece\n"
           "  size (scope.size.x * (1 - 0.5 * gap), h, 1 + gap)\n  " + item + "\n}\n";
}

/// The bounding box of `boxes` (axis-aligned ones).
Primitive boundingBox(const std::vector<Primitive>& boxes) {
    glm::vec3 lo = boxes[0].centre - boxes[0].half, hi = boxes[0].centre + boxes[0].half;
    for (const Primitive& p : boxes) {
        lo = glm::min(lo, p.centre - p.half);
        hi = glm::max(hi, p.centre + p.half);
    }
    Primitive out = boxes[0];
    out.centre = (lo + hi) * 0.5f;
    out.half = (hi - lo) * 0.5f;
    return out;
}

void expectNear(const std::vector<Primitive>& expected, const std::vector<Primitive>& got, int seed) {
    ASSERT_EQ(got.size(), expected.size()) << "seed " << seed;
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(got[i].centre[a], expected[i].centre[a], 1e-4) << "seed " << seed << " box " << i;
            EXPECT_NEAR(got[i].half[a], expected[i].half[a], 1e-4) << "seed " << seed << " box " << i;
        }
}

template <class Expected>
void forTiles(const std::string& steps, Expected expected) {
    const Grammar reference = parseGrammar(tiles("box", ""), "reference.grammar");
    const Grammar merged = parseGrammar(tiles("send items", steps), "merged.grammar");
    for (int seed = 1; seed <= 300; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(merged, c, rng, 10));
        const std::vector<Primitive> all = gather_test::deriveOne(reference, c).primitives;
        expectNear(expected(all), gather_test::deriveOne(merged, c).primitives, seed);
    }
}
}  // namespace gather_groups_test

TEST(GatherGroups, UnifyThenMergeMakesOneBoxPerRunOfTouchingBoxes) {
    forTiles("    unify\n    merge", [](const std::vector<Primitive>& all) {
        std::vector<Primitive> expected, run;
        for (std::size_t i = 0; i < all.size(); ++i) {
            run.push_back(all[i]);
            const bool touchesNext = i + 1 < all.size() &&
                                     std::fabs((all[i].centre.x + all[i].half.x) - (all[i + 1].centre.x - all[i + 1].half.x)) < 1e-3f;
            if (!touchesNext) {
                expected.push_back(boundingBox(run));
                run.clear();
            }
        }
        return expected;
    });
}

TEST(GatherGroups, MergeWithoutGroupsMakesOneBoxOfTheWholeList) {
    forTiles("    merge", [](const std::vector<Primitive>& all) {
        return all.empty() ? std::vector<Primitive>{} : std::vector<Primitive>{boundingBox(all)};
    });
}

TEST(GatherGroups, MergeAfterGroupByMakesOneBoxPerGroupInOrderOfFirstAppearance) {
    forTiles("    group by scope.size.z\n    merge", [](const std::vector<Primitive>& all) {
        std::vector<Primitive> expected;
        for (const auto& group : groupsBy(all, depth)) {
            std::vector<Primitive> members;
            for (std::size_t i : group) members.push_back(all[i]);
            expected.push_back(boundingBox(members));
        }
        return expected;
    });
}

}  // namespace shapevo
