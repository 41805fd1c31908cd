// PCGR's Fig. 4 stairway (grammars/pcg/stairway.pcg) derives what its graph says: a `copy` node
// makes as many pieces as its count input and its successors read the copy's place as
// piece.index, so the stairway has steps × flights treads, and tread k = i + c · steps (i the
// count node's index, c the copy node's copy index) stands k · rise above the first and is turned
// by k · turn about the axis, under one column as high as all of them; a copy node whose count
// is 0 makes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "grammar/pcg/pcg_front_end.hpp"

namespace shapevo {
namespace pcg_stairway_test_helpers {

using test::sourcePath;

/// The stairway graph's parameters, as its gene holds them.
struct StairParams {
    float steps = 0, flights = 0, rise = 0, turn = 0, radius = 0, depth = 0;
};


StairParams paramsOf(const Grammar& g, const Chromosome& c) {
    return {test::startParam(g, c, "steps"),  test::startParam(g, c, "flights"), test::startParam(g, c, "rise"),
            test::startParam(g, c, "turn"),   test::startParam(g, c, "radius"),  test::startParam(g, c, "depth")};
}

/// Degrees from `from` to `to` about +y, in (-180, 180].
double turnBetween(const glm::vec3& from, const glm::vec3& to) {
    const double a = std::atan2(double(from.z) * to.x - double(from.x) * to.z, double(from.x) * to.x + double(from.z) * to.z);
    return a * 180.0 / 3.14159265358979323846;
}
double wrapDegrees(double d) {
    d = std::fmod(d, 360.0);
    if (d <= -180.0) d += 360.0;
    if (d > 180.0) d -= 360.0;
    return d;
}

}  // namespace pcg_stairway_test_helpers

using namespace pcg_stairway_test_helpers;

TEST(PcgStairway, TheCopyNodeBecomesACopyStatementWhoseSuccessorsReadPieceIndex) {
    const std::string path = sourcePath("grammars/pcg/stairway.pcg");
    const Translation t = pcg::translatePcg(test::readFile(path), path);
    EXPECT_NE(t.text.find("copy steps {"), std::string::npos) << t.text;
    EXPECT_NE(t.text.find("copy flights {"), std::string::npos) << t.text;
    EXPECT_NE(t.text.find("rotate y piece.index * turn"), std::string::npos) << t.text;
}

TEST(PcgStairway, EveryTreadStandsOneRiseAboveAndOneTurnBeyondTheTreadItsIndexFollows) {
    const Grammar g = loadGrammar(sourcePath("grammars/pcg/stairway.pcg"));
    std::size_t flightsSeen = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng(seed);
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        ASSERT_EQ(c.genes, 1u) << "the whole stairway is one gene";
        const StairParams p = paramsOf(g, c);
        Geometry geo;
        DeriveScratch scratch;
        ASSERT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
        std::vector<Primitive> treads;
        std::size_t columns = 0;
        for (const Primitive& prim : geo.primitives) {
            if (prim.kind == PrimitiveKind::Box) treads.push_back(prim);
            columns += prim.kind == PrimitiveKind::Cylinder;
        }
        const std::size_t count = std::size_t(p.steps) * std::size_t(p.flights);
        ASSERT_EQ(treads.size(), count) << "seed " << seed << ": steps " << p.steps << " x flights " << p.flights;
        EXPECT_EQ(columns, 1u);
        flightsSeen += p.flights > 1.0f;
        std::sort(treads.begin(), treads.end(), [](const Primitive& a, const Primitive& b) { return a.centre.y < b.centre.y; });
        const float height = float(count) * p.rise;
        EXPECT_NEAR(treads.front().centre.y, -0.5f * height + 0.5f * p.rise, 1e-4f) << "seed " << seed;
        for (std::size_t k = 0; k < count; ++k) {
            const Primitive& t = treads[k];
            SCOPED_TRACE("seed " + std::to_string(seed) + ", tread " + std::to_string(k));
            EXPECT_NEAR(t.centre.y - treads.front().centre.y, float(k) * p.rise, 1e-4f);    // k rises up
            EXPECT_NEAR(wrapDegrees(turnBetween(treads.front().axes[0], t.axes[0]) - double(k) * p.turn), 0.0, 1e-3);  // k turns round
            EXPECT_NEAR(std::hypot(t.centre.x, t.centre.z), 0.5f * p.radius, 1e-4f);          // from the axis out
            EXPECT_NEAR(2.0f * t.half.x, p.radius, 1e-5f);
            EXPECT_NEAR(2.0f * t.half.y, p.rise, 1e-5f);
            EXPECT_NEAR(2.0f * t.half.z, p.depth, 1e-5f);
        }
        for (const Primitive& prim : geo.primitives)
            if (prim.kind == PrimitiveKind::Cylinder) EXPECT_NEAR(2.0f * prim.half.y, height, 1e-4f) << "seed " << seed;
    }
    EXPECT_GT(flightsSeen, 5u) << "some stairways copy their flight";
}

TEST(PcgStairway, ACopyNodeWithCountZeroMakesNothing) {
    test::TempDir dir;
    test::writeFile(dir.file("copies.pcg"),
                    "graph Copies\nattr n = 0\nin start : volume\nnode many = copy(count: n)\nnode ball = sphere()\n"
                    "node other = box()\nstart -> many, other\nmany -> ball\n");
    const Grammar g = loadGrammar(dir.file("copies.pcg"));
    Chromosome c;
    Rng rng(1);
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    Geometry geo;
    DeriveScratch scratch;
    ASSERT_EQ(derive(g, c, geo, scratch), DeriveStatus::Complete);
    ASSERT_EQ(geo.primitives.size(), 1u);
    EXPECT_EQ(geo.primitives[0].kind, PrimitiveKind::Box);
}

}  // namespace shapevo

namespace shapevo {

TEST(PcgStairway, TheAttributeMappedStairwayDerivesTheSameStairway) {
    // stairway-mapped.pcg maps both indices to carried attributes and turns each tread once by its
    // place k; stairway.pcg turns it twice: the same boxes up to float rounding, tread for tread
    const Grammar spent = loadGrammar(test::sourcePath("grammars/pcg/stairway.pcg"));
    const Grammar mapped = loadGrammar(test::sourcePath("grammars/pcg/stairway-mapped.pcg"));
    ASSERT_EQ(spent.rules[spent.start].geneWords(), mapped.rules[mapped.start].geneWords());
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(spent, c, rng, 10));
        const Geometry a = test::deriveComplete(spent, c), b = test::deriveComplete(mapped, c);
        ASSERT_EQ(a.primitives.size(), b.primitives.size()) << "seed " << seed;
        for (std::size_t i = 0; i < a.primitives.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(a.primitives[i].centre[k], b.primitives[i].centre[k], 1e-4f) << "seed " << seed << " primitive " << i;
                EXPECT_NEAR(a.primitives[i].half[k], b.primitives[i].half[k], 1e-5f) << "seed " << seed << " primitive " << i;
                for (int j = 0; j < 3; ++j)
                    EXPECT_NEAR(a.primitives[i].axes[k][j], b.primitives[i].axes[k][j], 1e-5f) << "seed " << seed;
            }
        }
    }
}

}  // namespace shapevo
