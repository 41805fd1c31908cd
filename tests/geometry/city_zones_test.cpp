// PCGR's Fig. 7 (grammars/city-zones.grammar) derives what the paper says, recomputed by brute
// force from the derived model's boxes alone: 1,024 blocks; downtown and the commercial ring are
// the blocks within the evolved fractions of the farthest block's distance from the blocks'
// mean; the rest (the periphery) is in min(k, n) neighbourhoods, each a fixed point of Lloyd's
// k-means (every block nearest its own neighbourhood's mean), alternately industrial and
// residential by number, and the 10 blocks of each nearest its mean are parks; building heights
// stay in their zone's range.
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
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace city_zones_test {


enum class Zone { Downtown, Commercial, Industrial, Residential, Park };

/// A block as the model shows it: its footprint's centre, its zone, its neighbourhood (the
/// periphery's; from its colour's tint) and its height.
struct Block {
    glm::dvec3 at;
    Zone zone;
    int hood = -1;
    double height;
};

Block blockOf(const Primitive& p, const Appearance& a) {
    Block b{glm::dvec3(p.centre.x, 0.0, p.centre.z), Zone::Downtown, -1, 2.0 * p.half.y};
    const float r = a.color[0], gr = a.color[1], bl = a.color[2];
    auto near = [](float x, float y) { return std::fabs(x - y) < 1e-4f; };
    if (near(gr, 0.62f) && near(r, 0.25f)) {
        b.zone = Zone::Park;
        b.hood = int(std::lround((bl - 0.1f) / 0.04f));
    } else if (near(gr, 0.45f)) {
        b.zone = Zone::Industrial;
        b.hood = int(std::lround((r - 0.5f) / 0.04f));
    } else if (near(gr, 0.8f)) {
        b.zone = Zone::Residential;
        b.hood = int(std::lround((r - 0.6f) / 0.04f));
    } else if (near(gr, 0.62f)) {
        b.zone = Zone::Commercial;
    } else {
        EXPECT_TRUE(near(r, 0.55f) && near(gr, 0.55f)) << "an unknown colour " << r << " " << gr << " " << bl;
    }
    return b;
}

}  // namespace city_zones_test

using namespace city_zones_test;

TEST(CityZones, ZonesNeighbourhoodsAndParksAreWhatBruteForceMakesOfTheBlocks) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/city-zones.grammar"));
    int hoodsSeen = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        ASSERT_EQ(c.genes, 1u) << "the whole city is one gene";
        Geometry geo;
        DeriveScratch scratch;
        ASSERT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
        ASSERT_EQ(geo.primitives.size(), 1024u);
        std::vector<Block> blocks;
        for (std::size_t i = 0; i < geo.primitives.size(); ++i) blocks.push_back(blockOf(geo.primitives[i], geo.appearance[i]));

        // zones: distance to the mean of all blocks, relative to the farthest
        glm::dvec3 centre(0.0);
        for (const Block& b : blocks) centre += b.at;
        centre /= double(blocks.size());
        double far = 0.0;
        for (const Block& b : blocks) far = std::max(far, glm::distance(b.at, centre));
        const double downtown = test::startParam(g, c, "downtown") * far, commercial = test::startParam(g, c, "commercial") * far;
        std::vector<const Block*> periphery;
        for (const Block& b : blocks) {
            const double d = glm::distance(b.at, centre);
            if (std::fabs(d - downtown) < 1e-3 || std::fabs(d - commercial) < 1e-3) continue;  // too near an edge to say
            const Zone expected = d <= downtown ? Zone::Downtown : d <= commercial ? Zone::Commercial : Zone::Industrial;
            if (expected == Zone::Industrial) {
                EXPECT_TRUE(b.zone == Zone::Industrial || b.zone == Zone::Residential || b.zone == Zone::Park) << d / far;
            } else {
                EXPECT_EQ(int(b.zone), int(expected)) << d / far;
            }
        }
        for (const Block& b : blocks)
            if (b.hood >= 0) periphery.push_back(&b);

        // neighbourhoods: min(k, n) of them, numbered 0.., each a fixed point of k-means
        std::map<int, std::vector<const Block*>> hoods;
        for (const Block* b : periphery) hoods[b->hood].push_back(b);
        const auto k = std::size_t(test::startParam(g, c, "k"));
        ASSERT_EQ(hoods.size(), std::min(k, periphery.size()));
        hoodsSeen += int(hoods.size());
        std::map<int, glm::dvec3> mean;
        for (const auto& [h, members] : hoods) {
            EXPECT_EQ(h, int(std::distance(hoods.begin(), hoods.find(h)))) << "numbered 0, 1, ...";
            glm::dvec3 sum(0.0);
            for (const Block* b : members) sum += b->at;
            mean[h] = sum / double(members.size());
        }
        for (const Block* b : periphery) {
            const double own = glm::distance(b->at, mean[b->hood]);
            for (const auto& [h, m] : mean) EXPECT_LE(own, glm::distance(b->at, m) + 1e-3) << "nearest its own centre";
            if (b->zone != Zone::Park)
                EXPECT_EQ(int(b->zone), int(b->hood % 2 == 0 ? Zone::Industrial : Zone::Residential)) << "alternate by number";
        }
        // parks: the 10 blocks of each neighbourhood nearest its mean
        for (const auto& [h, members] : hoods) {
            double farthestPark = 0.0, nearestOther = 1e30;
            std::size_t parks = 0;
            for (const Block* b : members) {
                const double d = glm::distance(b->at, mean[h]);
                if (b->zone == Zone::Park) {
                    ++parks;
                    farthestPark = std::max(farthestPark, d);
                } else {
                    nearestOther = std::min(nearestOther, d);
                }
            }
            EXPECT_EQ(parks, std::min<std::size_t>(10, members.size())) << "neighbourhood " << h;
            EXPECT_LE(farthestPark, nearestOther + 1e-3) << "neighbourhood " << h;
        }
        // heights: the zone's evolved height times the block's factor, in [0.8, 1.2]
        const std::map<Zone, float> heightOf = {{Zone::Downtown, test::startParam(g, c, "tall")}, {Zone::Commercial, test::startParam(g, c, "mid")},
                                                {Zone::Industrial, test::startParam(g, c, "wide")}, {Zone::Residential, test::startParam(g, c, "low")},
                                                {Zone::Park, 0.4f}};
        for (const Block& b : blocks) {
            if (b.zone == Zone::Park) {
                EXPECT_NEAR(b.height, 0.4, 1e-5);
                continue;
            }
            const double h = heightOf.at(b.zone);
            EXPECT_GE(b.height, 0.8 * h - 1e-3);
            EXPECT_LE(b.height, 1.2 * h + 1e-3);
        }
    }
    EXPECT_GT(hoodsSeen, 12 * 4 - 1) << "k is at least 4";
}

TEST(CityZones, TheSameGenomeGivesTheSameBitsTwice) {
    const Grammar g = loadGrammar(test::sourcePath("grammars/city-zones.grammar"));
    Chromosome c;
    Rng rng{5};
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    Geometry a, b;
    DeriveScratch s1, s2;
    ASSERT_EQ(derive(g, c, a, s1), DeriveStatus::Complete);
    ASSERT_EQ(derive(g, c, b, s2), DeriveStatus::Complete);
    ASSERT_EQ(derive(g, c, b, s2), DeriveStatus::Complete);  // a warm scratch too
    ASSERT_EQ(a.primitives.size(), b.primitives.size());
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        EXPECT_EQ(a.primitives[i].centre, b.primitives[i].centre);
        EXPECT_EQ(a.primitives[i].half, b.primitives[i].half);
    }
}

}  // namespace shapevo
