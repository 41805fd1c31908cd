// merge and unify (geometry/lists/merge.hpp, adjacency.hpp): the merged box bounds every member
// and touches each face, grid tiles merge into their union rectangle; unify's components equal a
// brute-force union-find over all pairs of edges on 1,000 random facade scenes, the corner tiles of
// two facades join, corners and gaps do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "../list_test_support.hpp"
#include "base/random.hpp"
#include "geometry/lists/adjacency.hpp"
#include "geometry/lists/merge.hpp"
#include "geometry/lists/ordering.hpp"

namespace shapevo::lists {
namespace list_merge_unify_test {

/// A face of a box as comp makes it (geometry/pieces.hpp): front (+z) or right (+x).
Scope boxFace(const Scope& box, bool right) {
    const glm::vec3 X = box.axes[0], Y = box.axes[1], Z = box.axes[2];
    Scope f = box;
    if (right) {
        f.origin = box.origin + X * (box.size.x * 0.5f);
        f.axes = glm::mat3(-Z, Y, X);
        f.size = glm::vec3(box.size.z, box.size.y, 0.0f);
    } else {
        f.origin = box.origin + Z * (box.size.z * 0.5f);
        f.axes = glm::mat3(X, Y, Z);
        f.size = glm::vec3(box.size.x, box.size.y, 0.0f);
    }
    return f;
}

/// Tile (column, row) of a face split into columns x rows.
Scope tile(const Scope& face, int columns, int rows, int column, int row) {
    Scope t = face;
    const float w = face.size.x / float(columns), h = face.size.y / float(rows);
    t.origin = face.origin + face.axes[0] * (-0.5f * face.size.x + (float(column) + 0.5f) * w) +
               face.axes[1] * (-0.5f * face.size.y + (float(row) + 0.5f) * h);
    t.size = glm::vec3(w, h, 0.0f);
    return t;
}

/// Edge adjacency written plainly (the definition of adjacency.hpp).
bool plainEdgesTouch(glm::dvec3 a0, glm::dvec3 a1, glm::dvec3 b0, glm::dvec3 b1, double tol) {
    const double la = glm::length(a1 - a0), lb = glm::length(b1 - b0);
    if (la <= tol || lb <= tol) return false;
    const glm::dvec3 da = (a1 - a0) / la, db = (b1 - b0) / lb;
    auto off = [](glm::dvec3 p, glm::dvec3 o, glm::dvec3 d) { return glm::length((p - o) - d * glm::dot(p - o, d)); };
    if (off(b0, a0, da) > tol || off(b1, a0, da) > tol || off(a0, b0, db) > tol || off(a1, b0, db) > tol) return false;
    const double s0 = glm::dot(b0 - a0, da), s1 = glm::dot(b1 - a0, da);
    return std::min(la, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1)) > tol;
}

/// Components by brute force: every pair of scopes, every pair of edges, union-find; labelled by
/// their smallest member, then numbered in order of first appearance.
std::vector<std::uint32_t> referenceComponents(const std::vector<Scope>& scopes, double tol) {
    const std::size_t n = scopes.size();
    std::vector<std::uint32_t> parent(n);
    for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
    auto find = [&](std::uint32_t i) {
        while (parent[i] != i) i = parent[i];
        return i;
    };
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = i + 1; j < n; ++j) {
            glm::dvec3 ci[4], cj[4];
            rectangleCorners(scopes[i], ci);
            rectangleCorners(scopes[j], cj);
            bool touch = false;
            for (int e = 0; e < 4 && !touch; ++e)
                for (int f = 0; f < 4 && !touch; ++f) touch = plainEdgesTouch(ci[e], ci[(e + 1) % 4], cj[f], cj[(f + 1) % 4], tol);
            if (touch) {
                const std::uint32_t a = find(i), b = find(j);
                parent[std::max(a, b)] = std::min(a, b);
            }
        }
    std::vector<std::uint32_t> label(n), number(n, ~0u);
    std::uint32_t next = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t root = find(i);
        if (number[root] == ~0u) number[root] = next++;
        label[i] = number[root];
    }
    return label;
}

TEST(ListMerge, BoundsEveryMemberCornerAndTouchesEachFaceOfItsBox) {
    Rng rng(53);
    for (int list = 0; list < 1000; ++list) {
        std::vector<Scope> members(1 + rng.below(8));
        for (Scope& s : members) {
            s.origin = glm::vec3(float(rng.normal() * 10), float(rng.normal() * 10), float(rng.normal() * 10));
            s.axes = test::list_support::randomRotationAxes(rng);
            s.size = glm::vec3(float(rng.uniform() * 5), float(rng.uniform() * 5), rng.below(2) ? 0.0f : float(rng.uniform() * 5));
        }
        const Scope m = mergeScopes(members);
        ASSERT_EQ(std::memcmp(&m.axes, &members[0].axes, sizeof m.axes), 0);
        double lowest[3] = {1e300, 1e300, 1e300}, highest[3] = {-1e300, -1e300, -1e300};
        glm::dvec3 corners[8];
        for (const Scope& s : members) {
            scopeCorners(s, corners);
            for (const glm::dvec3& c : corners)
                for (int a = 0; a < 3; ++a) {
                    const double t = glm::dot(c - glm::dvec3(m.origin), glm::dvec3(m.axes[a]));
                    ASSERT_LE(std::abs(t), 0.5 * m.size[a] + 1e-4);
                    lowest[a] = std::min(lowest[a], t);
                    highest[a] = std::max(highest[a], t);
                }
        }
        for (int a = 0; a < 3; ++a) {  // some corner reaches each face
            EXPECT_NEAR(lowest[a], -0.5 * m.size[a], 1e-4);
            EXPECT_NEAR(highest[a], 0.5 * m.size[a], 1e-4);
        }
    }
}

TEST(ListMerge, CoplanarGridTilesMergeIntoTheirUnionRectangle) {
    Scope box;
    box.origin = glm::vec3(3, 4, 5);
    box.size = glm::vec3(8, 6, 4);
    const Scope face = boxFace(box, false);
    std::vector<Scope> tiles;
    for (int column = 1; column < 3; ++column)
        for (int row = 0; row < 2; ++row) tiles.push_back(tile(face, 4, 3, column, row));  // columns 1-2, rows 0-1
    const Scope m = mergeScopes(tiles);
    EXPECT_NEAR(m.size.x, 4.0f, 1e-5f);
    EXPECT_NEAR(m.size.y, 4.0f, 1e-5f);
    EXPECT_EQ(m.size.z, 0.0f);
    EXPECT_NEAR(m.origin.x, 3.0f, 1e-5f);   // centred between columns 1 and 2 of 4
    EXPECT_NEAR(m.origin.y, 3.0f, 1e-5f);   // rows 0-1 of 3 over y in [1, 7]: [1, 5]
    EXPECT_NEAR(m.origin.z, 7.0f, 1e-5f);
}

TEST(ListUnify, EqualsBruteForceUnionFindOfEdgeAdjacencyOnRandomFacadeTiles) {
    Rng rng(59);
    Grouping g;
    ListWorkspace ws;
    std::vector<std::uint32_t> order;
    std::size_t joined = 0, total = 0;
    for (int scene = 0; scene < 1000; ++scene) {
        std::vector<Scope> tiles;
        const std::uint32_t boxes = 1 + rng.below(3);
        for (std::uint32_t b = 0; b < boxes; ++b) {
            Scope box;
            box.origin = glm::vec3(float(rng.below(3) * 6), 0.0f, float(rng.below(3) * 6));
            box.axes = rng.below(2) ? glm::mat3(1.0f) : test::list_support::randomRotationAxes(rng);
            box.size = glm::vec3(float(2 + rng.below(4)), float(2 + rng.below(4)), float(2 + rng.below(4)));
            for (const bool right : {false, true}) {
                const Scope face = boxFace(box, right);
                const int columns = 1 + int(rng.below(4)), rows = 1 + int(rng.below(3));
                for (int c = 0; c < columns; ++c)
                    for (int r = 0; r < rows; ++r)
                        if (rng.below(3) != 0) tiles.push_back(tile(face, columns, rows, c, r));
            }
        }
        for (std::uint32_t extra = rng.below(4); extra > 0; --extra) {  // loose flat scopes
            Scope s;
            s.origin = glm::vec3(float(rng.normal() * 5), float(rng.normal() * 5), float(rng.normal() * 5));
            s.axes = test::list_support::randomRotationAxes(rng);
            s.size = glm::vec3(float(1 + rng.uniform() * 3), float(1 + rng.uniform() * 3), 0.0f);
            tiles.push_back(s);
        }
        shuffleOrder(std::uint32_t(tiles.size()), rng.uniform(), 1, order);
        std::vector<Scope> shuffled;
        for (const std::uint32_t i : order) shuffled.push_back(tiles[i]);
        unifyAdjacent(shuffled, 1e-4, g, ws);
        ASSERT_EQ(g.groupOf, referenceComponents(shuffled, 1e-4)) << "scene " << scene;
        joined += shuffled.size() - g.count();
        total += shuffled.size();
    }
    EXPECT_GT(joined, total / 4);  // adjacency is common in these scenes
}

TEST(ListUnify, TheCornerTilesOfTwoFacadesLandInOneComponent) {
    Scope box;
    box.origin = glm::vec3(1, 2, 3);
    box.axes = glm::mat3(glm::mat3_cast(glm::rotate(glm::dquat(1, 0, 0, 0), 0.3, glm::dvec3(0, 1, 0))));
    box.size = glm::vec3(6, 3, 4);
    // One floor: the front's left and right tiles, the right facade's left (front corner) and right tiles.
    const Scope front = boxFace(box, false), right = boxFace(box, true);
    const std::vector<Scope> floor{tile(front, 3, 1, 0, 0), tile(front, 3, 1, 2, 0), tile(right, 3, 1, 0, 0), tile(right, 3, 1, 2, 0)};
    Grouping g;
    ListWorkspace ws;
    unifyAdjacent(floor, 1e-4, g, ws);
    EXPECT_EQ(g.groupOf, (std::vector<std::uint32_t>{0, 1, 1, 2}));
}

TEST(ListUnify, TilesTouchingOnlyAtACornerOrAcrossAGapStayApart) {
    Scope face;
    face.size = glm::vec3(4, 4, 0);
    const std::vector<Scope> diagonal{tile(face, 2, 2, 0, 0), tile(face, 2, 2, 1, 1)};
    Grouping g;
    ListWorkspace ws;
    unifyAdjacent(diagonal, 1e-4, g, ws);
    EXPECT_EQ(g.count(), 2u);
    Scope a = tile(face, 2, 2, 0, 0), b = tile(face, 2, 2, 1, 0);
    b.origin.x += 1e-3f;  // a gap wider than the tolerance
    unifyAdjacent(std::vector<Scope>{a, b}, 1e-4, g, ws);
    EXPECT_EQ(g.count(), 2u);
    b.origin.x -= 1e-3f - 2e-5f;  // within the tolerance
    unifyAdjacent(std::vector<Scope>{a, b}, 1e-4, g, ws);
    EXPECT_EQ(g.count(), 1u);
}

}  // namespace list_merge_unify_test
}  // namespace shapevo::lists
