// group by and ungroup (geometry/lists/grouping.hpp) against a plain first-appearance grouping on
// 1,000 random lists (NaN and -0 keys included); tiles by floor; ungroup restores the entities bit
// for bit in list order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "../list_test_support.hpp"
#include "base/random.hpp"
#include "geometry/lists/grouping.hpp"

namespace shapevo::lists {
namespace list_group_test {

using test::list_support::randomValue;
using test::list_support::referenceGroups;

std::vector<std::vector<std::uint32_t>> groupsOf(const Grouping& g) {
    std::vector<std::vector<std::uint32_t>> out;
    for (std::uint32_t k = 0; k < g.count(); ++k) out.emplace_back(g.group(k).begin(), g.group(k).end());
    return out;
}

Scope randomScope(Rng& rng) {
    Scope s;
    s.origin = glm::vec3(float(rng.uniform()), float(rng.normal()), float(rng.uniform() * 100));
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) s.axes[c][r] = float(rng.normal());
    s.size = glm::vec3(float(rng.uniform()), 0.0f, float(rng.uniform()));
    s.look = rng.below(5);
    return s;
}

TEST(ListGroupBy, GroupsComeInOrderOfFirstAppearanceWithMembersInListOrder) {
    Rng rng(29);
    Grouping g;
    ListWorkspace ws;
    for (int list = 0; list < 1000; ++list) {
        const std::uint32_t n = rng.below(60), m = 1 + rng.below(2);
        std::vector<double> keys(n * m);
        for (double& k : keys) {
            const std::uint32_t r = rng.below(12);
            k = r == 0 ? std::numeric_limits<double>::quiet_NaN() : r == 1 ? -0.0 : double(rng.below(4));
        }
        groupBy(keys, m, g, ws);
        const auto reference = referenceGroups(keys, m);
        ASSERT_EQ(groupsOf(g), reference) << "list " << list;
        ASSERT_EQ(g.groupOf.size(), n);
        for (std::uint32_t k = 0; k < g.count(); ++k)
            for (const std::uint32_t i : g.group(k)) ASSERT_EQ(g.groupOf[i], k);
    }
}

TEST(ListGroupBy, TilesGroupedByFloorGiveOneGroupPerFloorWithItsTiles) {
    // 3 facades x 4 floors x 5 columns, listed facade by facade; the key is the floor.
    std::vector<double> floors;
    for (int facade = 0; facade < 3; ++facade)
        for (int floor = 0; floor < 4; ++floor)
            for (int column = 0; column < 5; ++column) floors.push_back(floor);
    Grouping g;
    ListWorkspace ws;
    groupBy(floors, 1, g, ws);
    ASSERT_EQ(g.count(), 4u);
    for (std::uint32_t k = 0; k < 4; ++k) {
        ASSERT_EQ(g.group(k).size(), 15u);
        for (const std::uint32_t i : g.group(k)) EXPECT_EQ(floors[i], double(k));
    }
}

TEST(ListUngroup, RestoresTheOriginalEntitiesBitForBitInOrder) {
    Rng rng(31);
    EntityList list, grouped, restored;
    Grouping g;
    ListWorkspace ws;
    for (int round = 0; round < 1000; ++round) {
        const std::uint32_t n = rng.below(40), width = rng.below(4);
        list.clear(width);
        std::vector<double> keys(n), attrs(width);
        for (std::uint32_t i = 0; i < n; ++i) {
            for (double& a : attrs) a = randomValue(rng, true);
            list.append(randomScope(rng), attrs);
            keys[i] = double(rng.below(5));
        }
        groupBy(keys, 1, g, ws);
        selectEntities(list, g.members, grouped);
        ungroupEntities(grouped, g, restored);
        ASSERT_EQ(restored.size(), n);
        ASSERT_EQ(restored.width, width);
        if (n > 0) {
            ASSERT_EQ(std::memcmp(restored.scopes.data(), list.scopes.data(), n * sizeof(Scope)), 0);
        }
        if (!list.values.empty()) {
            ASSERT_EQ(std::memcmp(restored.values.data(), list.values.data(), list.values.size() * sizeof(double)), 0);
        }
    }
}

}  // namespace list_group_test
}  // namespace shapevo::lists
