// piece.index and piece.count: a piece's place among the pieces its statement made (layout
// order, nil pieces counted) and how many, in split, repeat, comp, lots and copy; 0 and 1 outside
// every piece; `[ ]` keeps the enclosing place; a child gene reads the place of the piece it was
// derived in. `copy N` makes N pieces of the scope itself (N clamped like repeat count's).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "genome/sample.hpp"
#include "geometry/derive.hpp"
#include "geometry/pieces.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace piece_place_test {

Geometry derived(const std::string& text, std::size_t maxPrimitives = kDefaultMaxPrimitives) {
    const Grammar g = parseGrammar(text, "place.grammar");
    Chromosome c;
    Rng rng(3);
    EXPECT_TRUE(growUncontrolled(g, c, rng, 200));
    Geometry geo;
    DeriveScratch scratch;
    EXPECT_EQ(derive(g, c, geo, scratch, maxPrimitives), DeriveStatus::Complete);
    return geo;
}

/// (index, count) each box read, from the colour probe `color (piece.index / 10000, piece.count / 10000, 0)`
/// (exact for small numbers: both ways divide by 100 in float), ordered by the boxes' x.
std::vector<std::pair<int, int>> places(const Geometry& geo) {
    std::vector<std::pair<float, std::pair<int, int>>> byX;
    for (std::size_t i = 0; i < geo.primitives.size(); ++i) {
        const Appearance& a = geo.appearance.at(i);
        int index = -1, count = -1;
        for (int k = 0; k <= 4096; ++k) {
            if (float(k) / 10000.0f == a.color[0]) index = k;
            if (float(k) / 10000.0f == a.color[1]) count = k;
        }
        byX.push_back({geo.primitives[i].centre.x, {index, count}});
    }
    std::stable_sort(byX.begin(), byX.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<int, int>> out;
    for (const auto& p : byX) out.push_back(p.second);
    return out;
}

constexpr const char* kProbe = "{ color (piece.index / 10000, piece.count / 10000, 0) box }";

std::string with(std::string text) {
    for (std::size_t at; (at = text.find("PROBE")) != std::string::npos;) text.replace(at, 5, kProbe);
    return "start A\nrule A {\n" + text + "\n}\n";
}

using Places = std::vector<std::pair<int, int>>;

TEST(PiecePlace, SplitPiecesCountNilOnesInLayoutOrder) {
    EXPECT_EQ(places(derived(with("size (6, 1, 1) split x { 1: PROBE | 1: nil | 2: PROBE | ~1: PROBE }"))),
              (Places{{0, 4}, {2, 4}, {3, 4}}));
}

TEST(PiecePlace, RepeatPiecesAreNumberedFromTheLowEnd) {
    EXPECT_EQ(places(derived(with("size (5, 1, 1) repeat x count 5 PROBE | PROBE"))),
              (Places{{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}}));
    EXPECT_EQ(places(derived(with("size (5, 1, 1) repeat x 2 PROBE"))), (Places{{0, 2}, {1, 2}}));
}

TEST(PiecePlace, CompFacesAreNumberedInTheOrderTheyAreListed) {
    // top, then side's four faces (front, right, back, left); x orders them: left, (top, front, back), right
    const Geometry geo = derived(with("comp { top: PROBE | side: PROBE }"));
    ASSERT_EQ(geo.primitives.size(), 5u);
    const Places read = places(geo);
    const std::set<std::pair<int, int>> seen(read.begin(), read.end());
    EXPECT_EQ(seen, (std::set<std::pair<int, int>>{{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}}));
    EXPECT_EQ(read.front(), (std::pair<int, int>{4, 5})) << "left, the last face";
    EXPECT_EQ(read.back(), (std::pair<int, int>{2, 5})) << "right, the second of side's";
}

TEST(PiecePlace, OutsideEveryPieceIndexIsZeroAndCountOne) {
    EXPECT_EQ(places(derived(with("color (piece.index / 10000, piece.count / 10000, 0) box"))), (Places{{0, 1}}));
}

TEST(PiecePlace, NestedPiecesSeeTheInnermostAndABracketBlockKeepsTheEnclosing) {
    EXPECT_EQ(places(derived(with("size (4, 2, 1) repeat x count 2 { repeat y count 3 PROBE }"))),
              (Places{{0, 3}, {1, 3}, {2, 3}, {0, 3}, {1, 3}, {2, 3}}));
    EXPECT_EQ(places(derived(with("size (4, 1, 1) repeat x count 2 { [ translate (0, 1, 0) color (piece.index / 10000, "
                                  "piece.count / 10000, 0) box ] }"))),
              (Places{{0, 2}, {1, 2}}));
}

TEST(PiecePlace, AChildInAPieceReadsThePlaceOfItsPiece) {
    const Geometry geo = derived("start A\nrule A { size (6, 1, 1) repeat x count 3 { child B } }\n"
                                 "rule B { size (1, piece.index + 1, piece.count) box }\n");
    ASSERT_EQ(geo.primitives.size(), 3u);
    std::vector<std::pair<float, float>> heights;
    for (const Primitive& p : geo.primitives) heights.push_back({p.centre.x, 2 * p.half.y});
    std::sort(heights.begin(), heights.end());
    EXPECT_EQ(heights, (std::vector<std::pair<float, float>>{{-2, 1}, {0, 2}, {2, 3}}));
    for (const Primitive& p : geo.primitives) EXPECT_EQ(2 * p.half.z, 3.0f);
}

TEST(PiecePlace, CopyMakesNPiecesOfTheScopeItselfNumberedZeroToNMinusOne) {
    const Geometry geo = derived(with("translate (2, 0, 0) copy 5 { translate (piece.index, 0, 0) "
                                      "color (piece.index / 10000, piece.count / 10000, 0) box }"));
    EXPECT_EQ(places(geo), (Places{{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}}));
    std::vector<float> xs;
    for (const Primitive& p : geo.primitives) {
        EXPECT_EQ(p.half, glm::vec3(0.5f)) << "every copy is the whole scope";
        xs.push_back(p.centre.x);
    }
    std::sort(xs.begin(), xs.end());
    EXPECT_EQ(xs, (std::vector<float>{2, 3, 4, 5, 6})) << "each moved by its own index from the scope's origin";
    EXPECT_EQ(places(derived(with("copy 1 PROBE"))), (Places{{0, 1}}));
    EXPECT_EQ(places(derived(with("copy 2.9 PROBE | { translate (0, 5, 0) color (piece.index / 10000, piece.count / 10000, 1) box }"))),
              (Places{{0, 2}, {1, 2}})) << "rounded down; successors in turn";
}

TEST(PiecePlace, CopyOfNothingNaNOrMinusMakesNoneAndAHugeCountStopsAtTheLimit) {
    for (const char* n : {"0", "0 / 0", "-3", "1 / 0"}) {
        SCOPED_TRACE(n);
        EXPECT_EQ(derived(with(std::string("box copy ") + n + " PROBE")).primitives.size(), 1u);
    }
    const Geometry huge = derived(with("copy 1e9 PROBE"), 8192);
    ASSERT_EQ(huge.primitives.size(), std::size_t(kMaxPieces));
    EXPECT_EQ(places(huge).back().second, int(kMaxPieces));
}

TEST(PiecePlace, AGrammarThatReadsNoPlaceDoesNotMarkPieces) {
    EXPECT_TRUE(parseGrammar(with("copy 3 PROBE"), "t.grammar").marksPieces);
    const Grammar plain = parseGrammar("start A\nrule A { copy 3 { box } repeat x count 2 { box } }\n", "t.grammar");
    EXPECT_FALSE(plain.usesPiecePlaces);
    EXPECT_FALSE(plain.marksPieces);
}

}  // namespace piece_place_test
}  // namespace shapevo
