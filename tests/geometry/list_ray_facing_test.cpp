// ray cast and facing of geometry/lists (ray_cast.hpp, facing.hpp, box_tree.hpp) against brute
// force: the nearest hit over every box with a plainly written ray / oriented-box test (the box
// inverted as a matrix) on 1,000 random scenes, the tree equal to testing every box exactly, and
// facing against dense sampling of the streets on synthetic boxes with and without an occluder.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "../list_test_support.hpp"
#include "base/random.hpp"
#include "geometry/lists/facing.hpp"
#include "geometry/lists/ray_cast.hpp"

namespace shapevo::lists {
namespace list_ray_facing_test {

constexpr double kMiss = std::numeric_limits<double>::infinity();

/// Ray / oriented box, written plainly: the ray in the box's unit-cube coordinates through the
/// inverse of its frame matrix, then the slab test; the first distance >= 0 inside, else kMiss.
double plainRayBox(glm::dvec3 origin, glm::dvec3 direction, const Scope& box) {
    const glm::dmat3 inverse = glm::inverse(glm::dmat3(box.axes));
    const glm::dvec3 o = inverse * (origin - glm::dvec3(box.origin)), d = inverse * direction;
    double enter = 0.0, leave = kMiss;
    for (int a = 0; a < 3; ++a) {
        const double half = 0.5 * double(box.size[a]);
        if (d[a] == 0.0) {
            if (o[a] < -half || o[a] > half) return kMiss;
            continue;
        }
        const double t1 = (-half - o[a]) / d[a], t2 = (half - o[a]) / d[a];
        enter = std::max(enter, std::min(t1, t2));
        leave = std::min(leave, std::max(t1, t2));
    }
    return enter <= leave ? enter : kMiss;
}

bool sameScope(const Scope& a, const Scope& b) { return a.origin == b.origin && a.axes == b.axes && a.size == b.size; }

/// The nearest of `targets` along the caster's ray by `distance(origin, direction, box)` (ties:
/// the lowest index), skipping targets equal to the caster when `skipSelf`; every box tried.
struct BruteHit {
    glm::dvec3 origin, direction;
    double distance = kMiss;
    std::uint32_t index = kNoBox;
};
template <class Distance>
BruteHit bruteNearest(const Scope& caster, RayAxis along, const std::vector<Scope>& targets, Distance distance, bool skipSelf) {
    BruteHit h;
    casterRay(caster, along, h.origin, h.direction);
    for (std::uint32_t j = 0; j < targets.size(); ++j) {
        if (skipSelf && sameScope(targets[j], caster)) continue;
        const double t = distance(h.origin, h.direction, targets[j]);
        if (t < h.distance) h.distance = t, h.index = j;
    }
    return h;
}

std::vector<Scope> randomBoxes(Rng& rng, std::uint32_t n, double spread) {
    std::vector<Scope> boxes(n);
    for (Scope& s : boxes) {
        s.origin = glm::vec3(float(rng.normal() * spread), float(rng.normal() * spread), float(rng.normal() * spread));
        s.axes = rng.below(4) == 0 ? glm::mat3(1.0f) : test::list_support::randomRotationAxes(rng);
        s.size = glm::vec3(float(0.2 + rng.uniform() * 4), float(0.2 + rng.uniform() * 4), rng.below(3) == 0 ? 0.0f : float(0.2 + rng.uniform() * 4));
    }
    return boxes;
}

/// A box standing on y = 0 at (x, z), axis-aligned, and its four side facades as comp makes them.
Scope building(float x, float z, float w, float h, float d) {
    Scope s;
    s.origin = glm::vec3(x, h * 0.5f, z);
    s.size = glm::vec3(w, h, d);
    return s;
}
void appendFacades(const Scope& b, std::vector<Scope>& out) {
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    auto face = [&](glm::vec3 centre, glm::vec3 x, glm::vec3 z, float width) {
        Scope f;
        f.origin = centre;
        f.axes = glm::mat3(x, Y, z);
        f.size = glm::vec3(width, b.size.y, 0.0f);
        out.push_back(f);
    };
    face(b.origin + Z * (b.size.z * 0.5f), X, Z, b.size.x);     // front
    face(b.origin - Z * (b.size.z * 0.5f), -X, -Z, b.size.x);   // back
    face(b.origin + X * (b.size.x * 0.5f), -Z, X, b.size.z);    // right
    face(b.origin - X * (b.size.x * 0.5f), Z, -X, b.size.z);    // left
}

/// Facing by brute force: `samples` points per street; in view within the tolerance, and (if
/// asked) no other shape hit before the point. Returns how many sample points are seen.
std::uint32_t seenSamples(const std::vector<Scope>& shapes, std::uint32_t i, const std::vector<StreetSegment>& streets,
                          double degrees, bool unoccluded, std::uint32_t samples) {
    const glm::dvec3 c(shapes[i].origin), n = glm::normalize(glm::dvec3(shapes[i].axes[2]));
    const double cosTolerance = std::cos(degrees * M_PI / 180.0);
    std::uint32_t seen = 0;
    for (const StreetSegment& s : streets)
        for (std::uint32_t k = 0; k < samples; ++k) {
            const glm::dvec3 p = s.a + (s.b - s.a) * (double(k) / double(samples - 1)), v = p - c;
            const double length = glm::length(v);
            if (length == 0.0 || glm::dot(n, v) / length < cosTolerance) continue;
            bool blocked = false;
            for (std::uint32_t j = 0; j < shapes.size() && unoccluded && !blocked; ++j)
                blocked = j != i && plainRayBox(c, v / length, shapes[j]) < length;
            seen += !blocked;
        }
    return seen;
}


TEST(ListRayCast, EqualsBruteForceRayOrientedBoxIntersectionOn1000RandomScenes) {
    Rng rng(61);
    BoxTree tree;
    std::size_t hits = 0, rays = 0;
    for (int scene = 0; scene < 1000; ++scene) {
        const std::vector<Scope> targets = randomBoxes(rng, 1 + rng.below(40), 3.0 + rng.uniform() * 10);
        const bool self = rng.below(3) == 0;  // cast the list against itself
        const std::vector<Scope> casters = self ? targets : randomBoxes(rng, 1 + rng.below(40), 8.0);
        const RayAxis along{std::uint8_t(rng.below(3)), rng.below(2) == 1};
        std::vector<RayHit> out(casters.size());
        rayCast(casters, along, targets, tree, out);
        for (std::size_t i = 0; i < casters.size(); ++i) {
            const BruteHit h = bruteNearest(casters[i], along, targets, plainRayBox, true);
            const glm::dvec3 origin = h.origin, direction = h.direction;
            const double best = h.distance;
            const std::uint32_t bestIndex = h.index;
            ASSERT_EQ(out[i].hit, bestIndex != kNoBox) << "scene " << scene << " ray " << i;
            ++rays;
            if (!out[i].hit) continue;
            ++hits;
            const glm::dvec3 expected = origin + direction * best;
            ASSERT_LE(glm::length(out[i].point - expected), 1e-5 * std::max(1.0, glm::length(expected)));
            // The nearest box, or one the brute force finds at the same distance (within rounding).
            if (out[i].target != bestIndex) {
                ASSERT_NEAR(plainRayBox(origin, direction, targets[out[i].target]), best, 1e-9 * std::max(1.0, best));
            }
        }
    }
    EXPECT_GT(hits, rays / 20);  // the scenes make hits and misses
    EXPECT_LT(hits, rays);
}

TEST(ListRayCast, TheTreeEqualsTestingEveryBoxExactlyOnAThousandByAThousand) {
    Rng rng(67);
    const std::vector<Scope> targets = randomBoxes(rng, 1000, 25.0), casters = randomBoxes(rng, 1000, 25.0);
    BoxTree tree;
    std::vector<RayHit> out(casters.size());
    for (const RayAxis along : {RayAxis{0, false}, RayAxis{2, true}}) {
        rayCast(casters, along, targets, tree, out);
        for (std::size_t i = 0; i < casters.size(); ++i) {
            const BruteHit h = bruteNearest(casters[i], along, targets, rayBoxDistance, false);
            ASSERT_EQ(out[i].target, h.index) << i;
            ASSERT_EQ(out[i].distance, h.distance);
        }
    }
}

TEST(ListRayCast, StartsInsideABoxAtDistanceZeroAndSkipsItself) {
    Scope a, b;
    a.size = glm::vec3(2.0f);
    b.origin = glm::vec3(0.5f, 0.0f, 0.0f);  // a's centre lies inside b
    b.size = glm::vec3(2.0f);
    Scope far = a;
    far.origin = glm::vec3(0.0f, 0.0f, 10.0f);
    const std::vector<Scope> list{a, b, far};
    BoxTree tree;
    std::vector<RayHit> out(3);
    rayCast(list, RayAxis{2, false}, list, tree, out);
    EXPECT_TRUE(out[0].hit);
    EXPECT_EQ(out[0].target, 1u);  // not itself (index 0), but b, which it starts in
    EXPECT_EQ(out[0].distance, 0.0);
    EXPECT_EQ(out[1].target, 0u);
    EXPECT_FALSE(out[2].hit);      // nothing beyond the far box along +z
    rayCast(list, RayAxis{2, true}, list, tree, out);
    EXPECT_EQ(out[2].target, 0u);  // back at a and b, both at z = 1: the lower index
    EXPECT_NEAR(out[2].distance, 9.0, 1e-6);
}

TEST(ListRayCast, EqualDistancesGoToTheLowestIndexWhicheverPartOfTheTreeIsWalkedFirst) {
    // Two unit boxes side by side, x in [0, 1] (A, the last index) and [1, 2] (B, index 0); a ray up
    // x = 1 meets both at z = 5. Eight boxes far on each side put A and B into different halves of
    // the tree, and A's half is walked first.
    auto unitBox = [](float x, float z) {
        Scope s;
        s.origin = glm::vec3(x, 0.0f, z);
        return s;
    };
    std::vector<Scope> targets{unitBox(1.5f, 5.5f)};
    for (int k = 0; k < 8; ++k) targets.push_back(unitBox(10.0f + k, 50.0f));
    for (int k = 0; k < 8; ++k) targets.push_back(unitBox(-10.0f - k, 50.0f));
    targets.push_back(unitBox(0.5f, 5.5f));
    Scope caster;
    caster.origin = glm::vec3(1.0f, 0.0f, 0.0f);
    caster.size = glm::vec3(0.1f);
    BoxTree tree;
    std::vector<RayHit> out(1);
    rayCast(std::vector<Scope>{caster}, RayAxis{2, false}, targets, tree, out);
    ASSERT_TRUE(out[0].hit);
    EXPECT_EQ(out[0].distance, 5.0);
    EXPECT_EQ(out[0].target, 0u);
}

TEST(ListFacing, AgreesWithBruteForceRaySamplingOnSyntheticBoxesWithAndWithoutAnOccluder) {
    Rng rng(71);
    BoxTree tree;
    const std::vector<StreetSegment> streets{{{-60, 0.5, 30}, {60, 0.5, 30}}};
    int compared = 0, facingCount = 0, hiddenByOccluder = 0;
    for (int scene = 0; scene < 40; ++scene) {
        // A row of buildings behind the street (z < 10), optionally a long wall in between.
        std::vector<Scope> shapes;
        const int count = 1 + int(rng.below(5));
        for (int b = 0; b < count; ++b)
            appendFacades(building(float(-40 + 20 * b + rng.uniform() * 4), float(-rng.uniform() * 10), float(4 + rng.uniform() * 6),
                                   float(3 + rng.uniform() * 10), float(4 + rng.uniform() * 6)),
                          shapes);
        const std::size_t facadesOfBuildings = shapes.size();
        const bool occluder = scene % 2 == 1;
        if (occluder) appendFacades(building(0.0f, 20.0f, 200.0f, 40.0f, 1.0f), shapes);
        for (const double degrees : {20.0, 45.0, 70.0})
            for (const bool unoccluded : {false, true}) {
                FacingOptions options;
                options.toleranceDegrees = degrees;
                options.unoccluded = unoccluded;
                std::vector<std::uint8_t> out(shapes.size());
                facing(shapes, streets, options, tree, out);
                for (std::uint32_t i = 0; i < facadesOfBuildings; ++i) {
                    const std::uint32_t seen = seenSamples(shapes, i, streets, degrees, unoccluded, 2001);
                    if (seen > 0 && seen < 2001 / 32 * 2) continue;  // seen through a gap narrower than the sampling: ambiguous
                    ++compared;
                    ASSERT_EQ(out[i] != 0, seen > 0) << "scene " << scene << " shape " << i << " degrees " << degrees;
                    facingCount += out[i];
                    if (occluder && unoccluded && out[i] == 0 && seenSamples(shapes, i, streets, degrees, false, 2001) > 0)
                        ++hiddenByOccluder;
                }
            }
    }
    EXPECT_GT(compared, 400);
    EXPECT_GT(facingCount, compared / 10);
    EXPECT_GT(hiddenByOccluder, 40);  // the wall hides facades that face the street
}

TEST(ListFacing, WithoutOcclusionTheBestAngleIsExactOnRandomShapesAndStreets) {
    Rng rng(73);
    BoxTree tree;
    int agreed = 0;
    for (int scene = 0; scene < 1000; ++scene) {
        const std::vector<Scope> shapes = randomBoxes(rng, 1 + rng.below(10), 10.0);
        std::vector<StreetSegment> streets(1 + rng.below(3));
        for (StreetSegment& s : streets)
            s = {{rng.normal() * 20, rng.normal() * 20, rng.normal() * 20}, {rng.normal() * 20, rng.normal() * 20, rng.normal() * 20}};
        FacingOptions options;
        options.toleranceDegrees = 10 + rng.uniform() * 70;
        std::vector<std::uint8_t> out(shapes.size());
        facing(shapes, streets, options, tree, out);
        const double cosTolerance = std::cos(options.toleranceDegrees * M_PI / 180.0);
        for (std::uint32_t i = 0; i < shapes.size(); ++i) {
            // The best cosine over dense samples never beats the closed form, and comes close to it.
            const glm::dvec3 c(shapes[i].origin), n = glm::normalize(glm::dvec3(shapes[i].axes[2]));
            double bestSampled = -2.0, bestExact = -2.0, nearest = kMiss;
            for (const StreetSegment& s : streets) {
                double t = 0.0;
                bestExact = std::max(bestExact, bestViewCosine(c, n, s, t));
                for (int k = 0; k <= 4000; ++k) {
                    const glm::dvec3 v = s.a + (s.b - s.a) * (k / 4000.0) - c;
                    bestSampled = std::max(bestSampled, glm::dot(n, v) / glm::length(v));
                    nearest = std::min(nearest, glm::length(v));
                }
            }
            ASSERT_GE(bestExact, bestSampled - 1e-12);
            if (nearest < 1.0) continue;  // a street that close: the samples' angle steps are too coarse
            ASSERT_LE(bestExact - bestSampled, 1e-4);
            if (std::abs(bestSampled - cosTolerance) < 1e-4) continue;
            ASSERT_EQ(out[i] != 0, bestSampled >= cosTolerance);
            ++agreed;
        }
    }
    EXPECT_GT(agreed, 3000);
}

TEST(ListFacing, AWallBetweenHidesTheFrontAndMovingItAsideShowsIt) {
    std::vector<Scope> shapes;
    appendFacades(building(0, 0, 6, 6, 6), shapes);  // front facade (index 0) faces +z, the street is at z = 30
    const std::vector<StreetSegment> streets{{{-10, 1, 30}, {10, 1, 30}}};
    FacingOptions options;
    options.toleranceDegrees = 30;
    options.unoccluded = true;
    BoxTree tree;
    std::vector<std::uint8_t> out(shapes.size());
    facing(shapes, streets, options, tree, out);
    EXPECT_EQ(std::vector<std::uint8_t>(out.begin(), out.end()), (std::vector<std::uint8_t>{1, 0, 0, 0}));
    std::vector<Scope> withWall = shapes;
    appendFacades(building(0, 15, 100, 20, 1), withWall);
    out.assign(withWall.size(), 9);
    facing(withWall, streets, options, tree, out);
    EXPECT_EQ(out[0], 0);
    options.unoccluded = false;
    facing(withWall, streets, options, tree, out);
    EXPECT_EQ(out[0], 1);
    options.unoccluded = true;
    std::vector<Scope> wallAside = shapes;
    appendFacades(building(80, 15, 100, 20, 1), wallAside);  // the wall spans x in [30, 130]
    out.assign(wallAside.size(), 9);
    facing(wallAside, streets, options, tree, out);
    EXPECT_EQ(out[0], 1);
}

}  // namespace list_ray_facing_test
}  // namespace shapevo::lists
