// PCGR's Fig. 1, reduced (grammars/street-view.grammar), checked from the derived model: four
// facades per house; a green facade is within 40 degrees of some point of the street (by a dense
// brute-force sampling of the street), and every facade that no point of the street is within
// 40 degrees of is red; occlusion only turns facades red, and does on some; each roof's height
// is its house's level of detail, 1 to 3 by the distance from the street.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

TEST(StreetView, GreenFacadesSeeTheStreetWithinTheAngleAndOcclusionOnlyTurnsSomeRed) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/street-view.grammar"));
    const double cosTolerance = std::cos(40.0 * 3.14159265358979323846 / 180.0);
    std::size_t green = 0, occluded = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const Geometry geo = test::deriveComplete(g, c);
        std::size_t houses = 0, facades = 0;
        for (std::size_t i = 0; i < geo.primitives.size(); ++i) {
            const Primitive& p = geo.primitives[i];
            const glm::vec3 colour = geo.appearance[i].color;
            if (colour[0] == 0.85f) ++houses;
            if (p.kind == PrimitiveKind::Roof) {  // level of detail by the distance from the street
                const double lanes = std::fabs(double(p.centre.z)) / 12.0;
                if (std::fabs(lanes - std::round(lanes)) < 1e-3) continue;
                EXPECT_NEAR(2.0f * p.half.y, 0.6f * (1.0f + std::min(2.0f, std::floor(float(lanes)))), 1e-4f);
                continue;
            }
            const bool isGreen = colour[1] == 0.7f, isRed = colour[0] == 0.8f;
            if (!isGreen && !isRed) continue;
            ++facades;
            // the face the slab stands on: its centre and outward normal (the slab's thin axis, 0.05)
            int thin = 0;
            for (int a = 1; a < 3; ++a)
                if (p.half[a] < p.half[thin]) thin = a;
            ASSERT_NEAR(p.half[thin], 0.025f, 1e-5f);
            const glm::dvec3 normal = glm::normalize(glm::dvec3(p.axes[thin]));
            const glm::dvec3 centre = glm::dvec3(p.centre) - normal * double(p.half[thin]);
            double best = -2.0;
            for (int s = 0; s <= 20000; ++s) {
                const glm::dvec3 q(-50.0 + 100.0 * s / 20000.0, 0.0, 0.0);
                best = std::max(best, glm::dot(normal, glm::normalize(q - centre)));
            }
            if (std::fabs(best - cosTolerance) < 1e-3) continue;  // too near the cone's edge to say
            if (isGreen) {
                EXPECT_GE(best, cosTolerance) << "a green facade sees the street";
                ++green;
            } else if (best >= cosTolerance) {
                ++occluded;  // within the angle, but another facade is in the way
            }
        }
        EXPECT_EQ(houses, std::size_t(2 * test::startParam(g, c, "n")));
        EXPECT_EQ(facades, 4 * houses);
    }
    EXPECT_GT(green, 100u);
    EXPECT_GT(occluded, 5u) << "occlusion turns some facades within the angle red";
}

}  // namespace shapevo
