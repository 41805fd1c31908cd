// PCGR's Fig. 10, reduced (grammars/street-numbers.grammar), checked from the derived model: the
// road segments form one polyline (each starts where the one before ends, turned by the evolved
// angle); every segment has `lots` lots on each side; the buildings on the left (the road's -z
// side) carry the odd numbers 1, 3, 5, ... and those on the right the even ones, each side's
// numbers rising along the street; a building's height is 3 + number * rise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {

TEST(StreetNumbers, LotsOnBothSidesOfAPolylineAreNumberedOddLeftEvenRightAlongTheStreet) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/street-numbers.grammar"));
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const Geometry geo = test::deriveComplete(g, c);
        const auto segments = std::size_t(test::startParam(g, c, "segments")), lots = std::size_t(test::startParam(g, c, "lots"));
        const float length = test::startParam(g, c, "length"), turn = test::startParam(g, c, "turn"), rise = test::startParam(g, c, "rise");
        std::vector<Primitive> roads;
        std::map<int, Primitive> buildings;  // by number
        for (std::size_t i = 0; i < geo.primitives.size(); ++i) {
            if (geo.appearance[i].color[0] == 0.4f) {
                roads.push_back(geo.primitives[i]);
                continue;
            }
            const int number = int(std::lround((0.75f - geo.appearance[i].color[1]) / 0.01f));
            EXPECT_EQ(buildings.count(number), 0u) << "one building per number";
            buildings[number] = geo.primitives[i];
        }
        ASSERT_EQ(roads.size(), segments);
        ASSERT_EQ(buildings.size(), 2 * segments * lots);
        EXPECT_EQ(buildings.begin()->first, 1);
        EXPECT_EQ(buildings.rbegin()->first, int(2 * segments * lots));
        // the polyline: segment k + 1 starts where segment k ends, turned by `turn`
        for (std::size_t k = 0; k + 1 < segments; ++k) {
            const glm::vec3 end = roads[k].centre + roads[k].axes[0] * (length * 0.5f);
            const glm::vec3 start = roads[k + 1].centre - roads[k + 1].axes[0] * (length * 0.5f);
            EXPECT_LT(glm::distance(end, start), 1e-3f) << "joint " << k;
            const float degrees = std::acos(std::clamp(glm::dot(roads[k].axes[0], roads[k + 1].axes[0]), -1.0f, 1.0f)) * 57.29578f;
            EXPECT_NEAR(degrees, turn, 1e-2) << "joint " << k;
        }
        // each building: its side of its nearest road and how far along the street it stands
        std::map<int, double> along;
        for (const auto& [number, b] : buildings) {
            std::size_t k = 0;
            for (std::size_t j = 1; j < segments; ++j)
                if (glm::distance(b.centre, roads[j].centre) < glm::distance(b.centre, roads[k].centre)) k = j;
            const glm::vec3 offset = b.centre - roads[k].centre;
            const float side = glm::dot(offset, roads[k].axes[2]);
            EXPECT_EQ(side < 0.0f, number % 2 == 1) << "number " << number << ": odd on the left (-z), even on the right";
            along[number] = double(k) * length + glm::dot(offset, roads[k].axes[0]);
            EXPECT_NEAR(2.0f * b.half.y, 3.0f + float(number) * rise, 1e-3f) << "number " << number;
        }
        for (int n = 3; n <= int(2 * segments * lots); ++n) EXPECT_GT(along[n], along[n - 2]) << "number " << n << " after " << n - 2;
    }
}

}  // namespace shapevo
