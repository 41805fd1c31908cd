// The CastleMaker models shapevo ships (grammars/castlemaker/) have the structure the thesis
// describes: chapter 4's toy castle (3 blocks, 8 corner towers, 3 pyramid roofs, 100 border
// stones of random height and colour, the four stone roofs at 25 % each, the 7 x 5 window door
// or its random variant at 50 % each), §7.2's stochastic tower (towers of different heights that
// always end) and §7.3's toy skyscrapers (nine rules, over a million triangles).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "../test_support.hpp"
#include "genome/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "geometry/tessellation.hpp"
#include "grammar/crl/crl_syntax.hpp"
#include "grammar/front_ends.hpp"
#include "../kind_params.hpp"

namespace shapevo {
namespace {

using test::readFile;
using test::sourcePath;

struct Model {
    Chromosome c;
    Geometry geo;
};

Model sampleModel(const Grammar& g, std::uint64_t seed, std::uint32_t maxGenes = 1000) {
    Model m;
    Rng rng(seed);
    for (int attempt = 0; attempt < 100 && !growUncontrolled(g, m.c, rng, maxGenes); ++attempt) {
    }
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, m.c, m.geo, scratch), DeriveStatus::Complete);
    return m;
}

std::string materialOf(const Grammar& g, const Geometry& geo, std::size_t i) { return g.materialNames[geo.appearance[i].material]; }

TEST(CrlModels, ToyCastleHasTheStructureOfChapterFour) {
    const Grammar g = loadGrammar(sourcePath("grammars/castlemaker/toy-castle.rule"));
    std::map<std::string, int> roofs;  // the border stones' four volumes
    int doors = 0, fullDoors = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const Model m = sampleModel(g, seed);
        std::map<std::string, int> count;
        std::set<float> heights;
        std::vector<int> doorElements(2, 0);
        for (std::size_t i = 0; i < m.geo.primitives.size(); ++i) {
            const Primitive& p = m.geo.primitives[i];
            const std::string mat = materialOf(g, m.geo, i);
            ++count[mat + "/" + std::to_string(int(p.kind))];
            if (mat == "walls") {
                const float h = 2 * p.half.y;
                EXPECT_GE(h, 3.0f - 1e-4f);
                EXPECT_LE(h, 8.0f + 1e-4f);
                EXPECT_NEAR(p.centre.y, h / 2, 1e-3f) << "a stone stands on the ground";
                heights.insert(h);
                if (p.kind == PrimitiveKind::Box) ++roofs["cuboid"];
                else if (test::taperOf(p) == 1 && test::taperZOf(p) == 0) ++roofs["gable along X"];
                else if (test::taperOf(p) == 0 && test::taperZOf(p) == 1) ++roofs["gable along Y"];
                else if (std::fabs(test::taperOf(p) - 0.6f) < 1e-6f && std::fabs(test::taperZOf(p) - 0.6f) < 1e-6f) ++roofs["mansard"];
                else ADD_FAILURE() << "unexpected stone volume " << test::taperOf(p) << " " << test::taperZOf(p);
            }
            // the centre building's door faces: CRL x = +-10, |y| < 10, below 70 % of its 50 units
            if (p.kind == PrimitiveKind::Mesh && std::fabs(std::fabs(p.centre.x) - 10) < 1 && std::fabs(p.centre.z) < 10 && p.centre.y < 35)
                ++doorElements[p.centre.x > 0 ? 1 : 0];
        }
        const int box = int(PrimitiveKind::Box), roof = int(PrimitiveKind::Roof);
        EXPECT_EQ(count["grass/" + std::to_string(box)], 1) << "the lawn";
        EXPECT_EQ(count["walls/" + std::to_string(box)] + count["walls/" + std::to_string(roof)], 100) << "the border stones";
        EXPECT_EQ(count["blue/" + std::to_string(roof)], 3) << "one pyramid roof per block";
        EXPECT_EQ(count["green/" + std::to_string(int(PrimitiveKind::Cylinder))], 8) << "2 + 2 + 4 corner towers";
        EXPECT_EQ(count["orange/" + std::to_string(int(PrimitiveKind::Paraboloid))], 8) << "their parabolic roofs";
        EXPECT_GT(heights.size(), 90u) << "every stone draws its own height";
        for (int d : doorElements) {
            ++doors;
            if (d == 35) ++fullDoors;
            EXPECT_GE(d, 3 * 2);
            EXPECT_LE(d, 7 * 5);
        }
    }
    const double n = 200 * 100;
    for (const char* kind : {"cuboid", "gable along X", "gable along Y", "mansard"})
        EXPECT_NEAR(roofs[kind] / n, 0.25, 0.02) << kind;
    EXPECT_NEAR(double(fullDoors) / doors, 0.5, 0.08) << "the 7 x 5 door or its random variant";
}

TEST(CrlModels, ToyCastleBlocksStandWhereTheLotSplitPutsThem) {
    const Grammar g = loadGrammar(sourcePath("grammars/castlemaker/toy-castle.rule"));
    const Model m = sampleModel(g, 7);
    std::vector<glm::vec3> tops;  // the blue pyramid roofs: Left (CRL y -30..-10), Center, Right
    for (std::size_t i = 0; i < m.geo.primitives.size(); ++i)
        if (materialOf(g, m.geo, i) == "blue") tops.push_back(m.geo.primitives[i].centre);
    ASSERT_EQ(tops.size(), 3u);
    std::sort(tops.begin(), tops.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.z > b.z; });  // CRL y = -z
    EXPECT_NEAR(tops[0].z, 20, 1e-3) << "Left: CRL y in [-30, -10]";
    EXPECT_NEAR(tops[1].z, 0, 1e-3);
    EXPECT_NEAR(tops[2].z, -20, 1e-3);
    EXPECT_NEAR(tops[0].y, 20 + 0.5f * 0.5f * 20, 1e-3) << "a roof of half the block's height on a 20-unit block";
    EXPECT_NEAR(tops[1].y, 50 + 0.5f * 0.5f * 50, 1e-3) << "the centre block is 50 high";
}

TEST(CrlModels, StochasticTowersDifferAndAlwaysEnd) {
    const Grammar g = loadGrammar(sourcePath("grammars/castlemaker/stochastic-tower.rule"));
    std::set<std::uint32_t> genes;
    std::set<int> heights;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        const Model m = sampleModel(g, seed);
        ASSERT_FALSE(m.c.empty());
        genes.insert(m.c.genes);
        float top = 0;
        for (const Primitive& p : m.geo.primitives) top = std::max(top, p.centre.y + p.half.y);
        heights.insert(int(top));
    }
    EXPECT_GE(genes.size(), 4u) << "the recursion stacks different numbers of storeys";
    EXPECT_GE(heights.size(), 10u);
}

TEST(CrlModels, ToySkyscrapersAreNineRulesAndOverAMillionTriangles) {
    const std::string path = sourcePath("grammars/castlemaker/toy-skyscrapers.rule");
    const crl::File f = crl::readCrl(readFile(path), path);
    EXPECT_EQ(f.rules.size(), 9u);
    const Grammar g = loadGrammar(path);
    const Model m = sampleModel(g, 1);
    EXPECT_GT(tessellate(m.geo).triangles.size(), 1000000u);
}

}  // namespace
}  // namespace shapevo
