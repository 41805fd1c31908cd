// Textured materials in derive and tessellation: a `texture` statement fixes a texture frame
// that every primitive below measures its UVs in, in world units (geometry/texture_uv.hpp), so a
// box split into pieces has the UVs of the unsplit box (the same tile size, continuous across
// the cut), stretch factors scale them, faces read left to right from outside, and a cylinder's
// side is continuous except at its one seam. Also the planar rule itself and how looks combine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "geometry/tessellation.hpp"
#include "geometry/texture_look.hpp"
#include "geometry/texture_uv.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

/// A grammar in tests/data (where bricks.png is), its root-only derivation and its mesh.
struct Textured {
    Grammar grammar;
    Geometry geometry;
    Mesh mesh;
    explicit Textured(const std::string& rules) {
        grammar = parseGrammar("start A\n" + rules, test::sourcePath("tests/data/uv.grammar"));
        Rng rng(1);
        Chromosome c;
        plantRoot(grammar, c, rng);
        DeriveScratch scratch;
        EXPECT_EQ(derive(grammar, c, geometry, scratch), DeriveStatus::Complete);
        mesh = tessellate(geometry);
    }
};

glm::vec3 normalOf(const Mesh& m, std::size_t t) {
    const auto& tri = m.triangles[t];
    return glm::normalize(glm::cross(m.vertices[tri[1]] - m.vertices[tri[0]], m.vertices[tri[2]] - m.vertices[tri[0]]));
}

/// The UVs of the corners of the triangles facing `n` (world), by position.
std::vector<std::pair<glm::vec3, glm::vec2>> cornersFacing(const Mesh& m, const glm::vec3& n) {
    std::vector<std::pair<glm::vec3, glm::vec2>> out;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        if (glm::dot(normalOf(m, t), n) > 0.999f)
            for (std::uint32_t v : m.triangles[t]) out.push_back({m.vertices[v], m.uvs.at(v)});
    return out;
}

struct Range {
    float lo = INFINITY, hi = -INFINITY;
    void add(float x) { lo = std::min(lo, x), hi = std::max(hi, x); }
    float width() const { return hi - lo; }
};
Range uRange(const std::vector<std::pair<glm::vec3, glm::vec2>>& corners) {
    Range r;
    for (const auto& c : corners) r.add(c.second.x);
    return r;
}

TEST(TextureUv, PlanarRuleReadsEveryFaceLeftToRightFromOutside) {
    const TextureFrame f{{1, 2, 3}, glm::mat3(1.0f), {2, 4, 8}};
    const glm::vec3 p = glm::vec3(1, 2, 3) + glm::vec3(0.5f, 1.0f, 2.0f);  // d = (0.5, 1, 2)
    EXPECT_EQ(planarUv(f, {0, 0, 1}, p), glm::vec2(0.25f, 0.25f)) << "front: u = x / tile_x, v = y / tile_y";
    EXPECT_EQ(planarUv(f, {0, 0, -1}, p), glm::vec2(-0.25f, 0.25f)) << "back: right is -x";
    EXPECT_EQ(planarUv(f, {1, 0, 0}, p), glm::vec2(-0.25f, 0.25f)) << "right: u = -z / tile_z";
    EXPECT_EQ(planarUv(f, {-1, 0, 0}, p), glm::vec2(0.25f, 0.25f)) << "left: u = z / tile_z";
    EXPECT_EQ(planarUv(f, {0, 1, 0}, p), glm::vec2(0.25f, -0.25f)) << "top: v = -z / tile_z";
    EXPECT_EQ(planarUv(f, {0, -1, 0}, p), glm::vec2(0.25f, 0.25f)) << "bottom: v = z / tile_z";
    EXPECT_EQ(planarUv(f, {0.6f, 0, 0.8f}, p), glm::vec2(0.25f, 0.25f)) << "the largest component decides";
    const TextureFrame flat{{0, 0, 0}, glm::mat3(1.0f), {0.0f, INFINITY, NAN}};
    EXPECT_EQ(planarUv(flat, {0, 0, 1}, p - glm::vec3(1, 2, 3)), glm::vec2(0.0f, 0.0f)) << "no finite positive tile: 0";
}

TEST(TextureUv, TileLengthsAreSizeOverStretchAndAFlatScopeUsesX) {
    EXPECT_EQ(textureTile({4, 2, 6}, 2, 4), glm::vec3(2, 0.5f, 3));
    EXPECT_EQ(textureTile({4, 2, 0}, 2, 4), glm::vec3(2, 0.5f, 2)) << "size.z 0: tile_z = tile_x";
    EXPECT_EQ(textureTile({-4, 2, 6}, 2, 4), glm::vec3(2, 0.5f, 3)) << "a negative size is a length";
}

TEST(TextureUv, ASplitBoxKeepsTheWholeBoxsTileSizeAndIsContinuousAtTheCut) {
    const Textured whole("rule A { size (4, 2, 1) texture bricks \"bricks.png\" (2, 1) box }\n");
    const Textured split("rule A { size (4, 2, 1) texture bricks \"bricks.png\" (2, 1) split x { 1: { box } | ~1: { box } } }\n");
    ASSERT_EQ(split.geometry.primitives.size(), 2u);
    ASSERT_EQ(split.mesh.uvs.size(), split.mesh.vertices.size());
    const glm::vec3 faces[] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}};
    for (const glm::vec3& n : faces) {
        SCOPED_TRACE(testing::Message() << "face (" << n.x << ", " << n.y << ", " << n.z << ")");
        const auto a = cornersFacing(whole.mesh, n), b = cornersFacing(split.mesh, n);
        ASSERT_FALSE(a.empty());
        ASSERT_FALSE(b.empty());
        EXPECT_FLOAT_EQ(uRange(a).width(), 2.0f) << "4 units of a 2-unit tile";
        EXPECT_FLOAT_EQ(uRange(b).lo, uRange(a).lo);
        EXPECT_FLOAT_EQ(uRange(b).hi, uRange(a).hi);
        // every corner of the pieces has the UV the whole box has at that point: u = +-x / 2
        for (const auto& [p, uv] : b) EXPECT_FLOAT_EQ(std::fabs(uv.x), std::fabs(p.x) / 2.0f) << p.x;
        // at the cut (x = -1) both pieces' corners agree
        std::map<std::pair<float, float>, glm::vec2> atCut;
        int shared = 0;
        for (const auto& [p, uv] : b) {
            if (std::fabs(p.x + 1.0f) > 1e-6f) continue;
            const auto key = std::make_pair(p.y, p.z);
            const auto [it, added] = atCut.emplace(key, uv);
            if (!added) {
                EXPECT_EQ(it->second, uv) << "y " << p.y << " z " << p.z;
                ++shared;
            }
        }
        EXPECT_GT(shared, 0) << "both pieces have corners on the cut";
    }
}

TEST(TextureUv, DoublingTheStretchDoublesTheURange) {
    const Textured once("rule A { size (4, 2, 1) texture bricks \"bricks.png\" (2, 1) box }\n");
    const Textured twice("rule A { size (4, 2, 1) texture bricks \"bricks.png\" (4, 1) box }\n");
    const auto a = cornersFacing(once.mesh, {0, 0, 1}), b = cornersFacing(twice.mesh, {0, 0, 1});
    EXPECT_FLOAT_EQ(uRange(a).width(), 2.0f);
    EXPECT_FLOAT_EQ(uRange(b).width(), 4.0f);
    Range va, vb;
    for (const auto& c : a) va.add(c.second.y);
    for (const auto& c : b) vb.add(c.second.y);
    EXPECT_FLOAT_EQ(va.width(), 1.0f) << "SY 1: one tile over the height";
    EXPECT_FLOAT_EQ(vb.width(), va.width()) << "SX does not change v";
}

TEST(TextureUv, TheFrameIsTheScopeAtTheStatementNotTheOneAtThePrimitive) {
    // scaled and moved after the statement: the tiles stay where the statement put them
    const Textured t("rule A { size (4, 2, 1) texture bricks \"bricks.png\" (2, 1) scale (0.5, 1, 1) translate (1, 0, 0) box }\n");
    ASSERT_EQ(t.geometry.textureFrames.size(), 1u);
    EXPECT_EQ(t.geometry.textureFrames[0].tile, glm::vec3(2, 2, 0.5f));
    const Range u = uRange(cornersFacing(t.mesh, {0, 0, 1}));
    EXPECT_FLOAT_EQ(u.lo, 0.0f);  // x in [0, 2] of 2-unit tiles
    EXPECT_FLOAT_EQ(u.hi, 1.0f);
}

TEST(TextureUv, ACylindersSideIsContinuousExceptAtOneSeam) {
    // as it is, turned half around (its seam on the other side) and mirrored (its angles reversed)
    for (const char* turn : {"", "rotate y 180", "mirror z", "rotate y 90 mirror x"}) {
        SCOPED_TRACE(turn);
        const Textured t(std::string("rule A { size (2, 3, 2) texture bricks \"bricks.png\" (1, 1) ") + turn + " cylinder }\n");
        ASSERT_EQ(t.geometry.primitives.size(), std::string(turn).find("mirror") != std::string::npos ? 2u : 1u);
        const Mesh& m = t.mesh;
        const float tileX = 2.0f, radius = 1.0f, around = 2.0f * std::numbers::pi_v<float> * radius / tileX;
        // side corners by position and copy: one UV each, or two that differ by one turn in u
        std::map<std::tuple<std::size_t, float, float, float>, std::vector<glm::vec2>> uvsAt;
        int side = 0;
        const std::size_t perCopy = m.triangles.size() / t.geometry.primitives.size();
        for (std::size_t i = 0; i < m.triangles.size(); ++i) {
            if (std::fabs(normalOf(m, i).y) > 0.5f) continue;  // caps
            ++side;
            for (std::uint32_t v : m.triangles[i]) {
                auto& list = uvsAt[{i / perCopy, m.vertices[v].x, m.vertices[v].y, m.vertices[v].z}];
                if (std::none_of(list.begin(), list.end(), [&](const glm::vec2& uv) { return glm::length(uv - m.uvs[v]) < 1e-5f; }))
                    list.push_back(m.uvs[v]);
            }
        }
        EXPECT_EQ(side, 2 * kRoundSides * int(t.geometry.primitives.size()));
        Range u;
        int seam = 0;
        for (const auto& [p, list] : uvsAt) {
            for (const glm::vec2& uv : list) u.add(uv.x);
            ASSERT_LE(list.size(), 2u);
            if (list.size() == 2) {
                ++seam;
                EXPECT_NEAR(std::fabs(list[0].x - list[1].x), around, 1e-4f) << "the seam jumps by one turn";
                EXPECT_EQ(list[0].y, list[1].y);
                EXPECT_NEAR(std::fabs(std::get<1>(p)) + std::fabs(std::get<3>(p)), 1.0f, 1e-5f) << "on a ring vertex";
            }
            EXPECT_NEAR(list[0].y, std::get<2>(p) / 3.0f, 1e-6f) << "v = y / tile_y";
        }
        EXPECT_EQ(seam, 2 * int(t.geometry.primitives.size())) << "one seam edge per copy: its bottom and top vertex";
        EXPECT_NEAR(u.width(), around, 1e-4f) << "once around: 2 pi R / tile_x";
    }
}

TEST(TextureUv, OnACylindersFrontUGrowsToTheRightSeenFromOutside) {
    const Textured t("rule A { size (2, 3, 2) texture bricks \"bricks.png\" (1, 1) cylinder }\n");
    for (std::size_t i = 0; i < t.mesh.triangles.size(); ++i) {
        const glm::vec3 n = normalOf(t.mesh, i);
        if (std::fabs(n.y) > 0.5f || n.z < 0.9f) continue;  // the front of the side
        const auto& tri = t.mesh.triangles[i];
        for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) {
                const glm::vec3 &a = t.mesh.vertices[tri[std::size_t(k)]], &b = t.mesh.vertices[tri[std::size_t(l)]];
                if (a.x < b.x - 1e-4f) {
                    EXPECT_LT(t.mesh.uvs[tri[std::size_t(k)]].x, t.mesh.uvs[tri[std::size_t(l)]].x);
                }
            }
    }
}

TEST(TextureUv, APointedConesApexTakesTheAngleOfItsTriangle) {
    const Textured t("rule A { size (2, 2, 2) texture bricks \"bricks.png\" (1, 1) cone }\n");
    const Mesh& m = t.mesh;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        if (std::fabs(normalOf(m, i).y) > 0.7f) continue;
        float us[3];
        for (int k = 0; k < 3; ++k) us[k] = m.uvs[m.triangles[i][std::size_t(k)]].x;
        const float spread = std::max({us[0], us[1], us[2]}) - std::min({us[0], us[1], us[2]});
        EXPECT_LT(spread, 2.0f * std::numbers::pi_v<float> * 0.5f / 2.0f / kRoundSides * 1.01f) << "no triangle straddles the seam";
    }
}

TEST(TextureUv, TexturedPrimitivesGetOwnVerticesAndUntexturedOnesKeepTheirs) {
    const Textured t("rule A { color (1, 0, 0) box translate (3, 0, 0) texture bricks \"bricks.png\" (1, 1) box }\n");
    const Mesh& m = t.mesh;
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[0].texture, -1);
    EXPECT_EQ(m.materials[1].texture, 0);
    EXPECT_EQ(m.materials[1].name, "bricks");
    EXPECT_EQ(m.materials[1].color, glm::vec3(1.0f)) << "a textured material is white";
    ASSERT_EQ(m.textures.size(), 1u);
    EXPECT_EQ(m.textures[0].name, "bricks.png");
    EXPECT_EQ(m.textures[0].png, t.grammar.textures[0].png);
    ASSERT_EQ(m.uvs.size(), m.vertices.size());
    // the plain box shares its 8 corners; the textured one's corners are shared only by faces
    // that give them the same UV (at most 4 per face)
    EXPECT_GT(m.vertices.size(), 8u + 8u);
    EXPECT_LE(m.vertices.size(), 8u + 24u);
    for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(m.uvs[v], glm::vec2(0.0f));
    const TextureFrame& frame = t.geometry.textureFrames.at(0);
    for (std::size_t i = 12; i < m.triangles.size(); ++i)
        for (std::uint32_t v : m.triangles[i]) EXPECT_EQ(m.uvs[v], planarUv(frame, normalOf(m, i), m.vertices[v])) << i;
}

TEST(TextureUv, AColourOrMaterialAfterATextureEndsIt) {
    const Textured t("rule A { texture bricks \"bricks.png\" (1, 1) box color (1, 0, 0) box texture bricks \"bricks.png\" (1, 1) "
                     "material steel box }\n");
    ASSERT_EQ(t.geometry.appearance.size(), 3u);
    EXPECT_EQ(t.geometry.appearance[0].texture, 1);
    EXPECT_EQ(t.geometry.appearance[0].color, glm::vec3(1.0f));
    EXPECT_EQ(t.geometry.appearance[1].texture, 0);
    EXPECT_EQ(t.geometry.appearance[1].color, glm::vec3(1, 0, 0));
    EXPECT_EQ(t.geometry.appearance[2].texture, 0);
    EXPECT_EQ(t.geometry.textureFrames.size(), 2u);
}

TEST(TextureUv, PiecesAndChildrenInheritTheFrameAndMirrorsReadLeftToRight) {
    const Textured t("rule A { size (4, 1, 1) texture bricks \"bricks.png\" (4, 1) child B }\n"
                     "rule B { mirror x translate (1, 0, 0) scale (0.5, 1, 1) box }\n");
    ASSERT_EQ(t.geometry.primitives.size(), 2u);
    ASSERT_EQ(t.geometry.textureFrames.size(), 1u);
    // on both the plain and the mirrored copy the front face's u grows with world x
    for (std::size_t t0 = 0; t0 < t.mesh.triangles.size(); ++t0) {
        const auto& tri = t.mesh.triangles[t0];
        if (normalOf(t.mesh, t0).z < 0.999f) continue;
        for (std::uint32_t v : tri) EXPECT_FLOAT_EQ(t.mesh.uvs[v].x, t.mesh.vertices[v].x) << "tile_x = 1";
    }
}

}  // namespace
}  // namespace shapevo
