// The gather steps that look at other entities (grammars/README.md "Lists"): `let d =
// raycast(±AXIS, LIST)` and `let f = facing(LIST, DEGREES)`, per entity, against brute force on
// random genomes: the same model written without the gather emits every entity (and the street),
// and the reference casts each ray against every box, and samples the street densely.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "gather_test_support.hpp"

namespace shapevo {
namespace gather_look_test {

/// n boxes along x, each of its own width (a gap after some), height and depth; ITEM is what
/// each does, GATHER what the start rule does after.
std::string boxes(const std::string& item, const std::string& gather) {
    return "start S\nrule S {\n  param n = int(0, 16)\n  size (30, 4, 4)\n  repeat x count n Item\n" + gather +
           "}\nrule Item {\n  param w = uniform(0.3, 1) per piece\n  param h = uniform(0.5, 4) per piece\n"
           "  param d = uniform(0.5, 4) per piece\n  size (scope.size.x * w, h, d)\n  " + item + "\n}\n";
}

/// The distance along `dir` (a unit axis) from `o` to the axis-aligned box `b`, -1 if it misses.
double rayToBox(const glm::dvec3& o, const glm::dvec3& dir, const Primitive& b) {
    double lo = 0.0, hi = 1e30;
    for (int a = 0; a < 3; ++a) {
        const double mn = double(b.centre[a]) - b.half[a], mx = double(b.centre[a]) + b.half[a];
        if (dir[a] == 0.0) {
            if (o[a] < mn || o[a] > mx) return -1.0;
            continue;
        }
        double t0 = (mn - o[a]) / dir[a], t1 = (mx - o[a]) / dir[a];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
    }
    return lo <= hi ? lo : -1.0;
}

template <class Expected>
void forBoxes(const std::string& gather, const std::string& route, Expected expected) {
    const Grammar reference = parseGrammar(boxes("box", ""), "reference.grammar");
    const Grammar looked = parseGrammar(boxes("send items", "  gather items {\n" + gather + "\n" + route + "\n  }\n"), "look.grammar");
    for (int seed = 1; seed <= 300; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(looked, c, rng, 10));
        const std::vector<Primitive> all = gather_test::deriveOne(reference, c).primitives;
        const std::vector<Primitive> got = gather_test::deriveOne(looked, c).primitives;
        ASSERT_EQ(got.size(), all.size()) << seed;
        for (std::size_t i = 0; i < all.size(); ++i) EXPECT_NEAR(got[i].half.y, expected(all, i) * 0.5, 1e-4) << "seed " << seed << " box " << i;
    }
}

/// Box i's ray from its centre along `dir`: the nearest other box, by brute force (-1: none).
double nearestHit(const std::vector<Primitive>& all, std::size_t i, const glm::dvec3& dir) {
    double best = -1.0;
    for (std::size_t j = 0; j < all.size(); ++j) {
        if (j == i) continue;
        const double t = rayToBox(glm::dvec3(all[i].centre), dir, all[j]);
        if (t >= 0.0 && (best < 0.0 || t < best)) best = t;
    }
    return best;
}

}  // namespace gather_look_test

using namespace gather_look_test;

TEST(GatherLook, RaycastAlongPlusXIsTheDistanceToTheNearestOtherBoxOrMinusOne) {
    forBoxes("    let hit = raycast(+x, items)", "    each : { size (scope.size.x, hit + 2, scope.size.z) box }",
             [](const std::vector<Primitive>& all, std::size_t i) { return nearestHit(all, i, {1, 0, 0}) + 2.0; });
}

TEST(GatherLook, RaycastAlongMinusXLooksTheOtherWay) {
    forBoxes("    let hit = raycast(-x, items)", "    each : { size (scope.size.x, hit + 2, scope.size.z) box }",
             [](const std::vector<Primitive>& all, std::size_t i) { return nearestHit(all, i, {-1, 0, 0}) + 2.0; });
}

namespace gather_look_test {
/// Items turned about y by their own angle, a street along x at z = 20, and facing's tolerance t.
std::string turned(const std::string& item, const std::string& street, const std::string& gathers) {
    return "start S\nrule S {\n  param n = int(0, 16)\n  param t = uniform(5, 80)\n  size (30, 4, 4)\n  repeat x count n Item\n"
           "  [ translate (0, 0, 20) size (30, 1, 1) " + street + " ]\n" + gathers +
           "}\nrule Item {\n  param a = uniform(0, 360) per piece\n  rotate y a\n  size (1, 1, 1)\n  " + item + "\n}\n";
}
}  // namespace gather_look_test

TEST(GatherLook, FacingIsWhetherSomePointOfTheStreetIsWithinTheAngleOfTheShapesNormal) {
    const Grammar reference = parseGrammar(turned("box", "box", ""), "reference.grammar");
    const Grammar looked = parseGrammar(
        turned("send facades", "send streets",
               "  gather facades {\n    let f = facing(streets, t)\n    each : { size (1, 1 + f, 1) box }\n  }\n"
               "  gather streets {\n    each : nil\n  }\n"),
        "facing.grammar");
    int facingSeen = 0, awaySeen = 0;
    for (int seed = 1; seed <= 200; ++seed) {
        Chromosome c;
        Rng rng{std::uint64_t(seed)};
        ASSERT_TRUE(growUncontrolled(looked, c, rng, 10));
        std::vector<Primitive> all = gather_test::deriveOne(reference, c).primitives;
        const std::vector<Primitive> got = gather_test::deriveOne(looked, c).primitives;
        ASSERT_FALSE(all.empty());
        const auto isStreet = [](const Primitive& p) { return p.half.x == 15.0f; };  // 30 long; an item is 1
        const auto at = std::find_if(all.begin(), all.end(), isStreet);
        ASSERT_NE(at, all.end());
        const Primitive street = *at;
        all.erase(at);
        ASSERT_EQ(got.size(), all.size()) << seed;
        const double tolerance = std::cos(gather_test::param(looked, c, 1) * 3.14159265358979323846 / 180.0);
        const glm::dvec3 a = glm::dvec3(street.centre) - glm::dvec3(street.axes[0]) * double(street.half.x);
        const glm::dvec3 b = glm::dvec3(street.centre) + glm::dvec3(street.axes[0]) * double(street.half.x);
        for (std::size_t i = 0; i < all.size(); ++i) {
            const glm::dvec3 centre(all[i].centre), normal = glm::normalize(glm::dvec3(all[i].axes[2]));
            double best = -2.0;
            for (int s = 0; s <= 20000; ++s) {
                const glm::dvec3 p = a + (b - a) * (double(s) / 20000.0);
                best = std::max(best, glm::dot(normal, glm::normalize(p - centre)));
            }
            if (std::fabs(best - tolerance) < 1e-3) continue;  // too near the edge of the cone to say
            const bool faces = best >= tolerance;
            EXPECT_EQ(got[i].half.y * 2.0f, faces ? 2.0f : 1.0f) << "seed " << seed << " facade " << i;
            (faces ? facingSeen : awaySeen) += 1;
        }
    }
    EXPECT_GT(facingSeen, 50);
    EXPECT_GT(awaySeen, 50);
}

}  // namespace shapevo

namespace shapevo {

TEST(GatherLook, UnoccludedFacingNeedsALineOfSightPastTheListsOtherShapes) {
    for (const bool unoccluded : {false, true}) {
        const Grammar g = parseGrammar(
            std::string("start S\nrule S {\n  size (1, 1, 1)\n  [ size (1, 1, 0) send facades ]\n"
                        "  [ translate (0, 0, 10) size (100, 4, 0) send facades ]\n"
                        "  [ translate (0, 0, 20) size (30, 1, 1) send streets ]\n"
                        "  gather facades {\n    let f = facing(streets, 60") + (unoccluded ? ", unoccluded" : "") +
                ")\n    each : { size (1, 1 + f, 1) box }\n  }\n  gather streets {\n    each : nil\n  }\n}\n",
            "occluded.grammar");
        Chromosome c;
        Rng rng{1};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const std::vector<Primitive> got = gather_test::deriveOne(g, c).primitives;
        ASSERT_EQ(got.size(), 2u);
        for (const Primitive& p : got) {
            const bool behind = p.centre.z < 5.0f;  // the small one, behind the wide one
            EXPECT_EQ(p.half.y * 2.0f, behind && unoccluded ? 1.0f : 2.0f) << "unoccluded " << unoccluded << ", z " << p.centre.z;
        }
    }
}

}  // namespace shapevo
