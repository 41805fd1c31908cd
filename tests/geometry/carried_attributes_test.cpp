// Carried attributes (grammars/README.md "Carried attributes"): `carry NAME = VALUE` declares
// one, `set NAME = E` sets it on the current shape, and every shape derived from it inherits the
// value: pieces, inline calls, copies, child genes, entities sent to a list and their routes.
// Checked on random genomes against what each shape must read; a set that nothing reads changes
// nothing (the task goes on in order); the memo and the subtree starts keep carried values apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "base/random.hpp"
#include "genome/operators.hpp"
#include "genome/sample.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace carried_attributes_test {

/// A's box reads the default; B reads what A set (t), the right piece's B half of it, C (a child
/// gene) what A had set when the child statement ran.
constexpr const char* kInherit = R"(carry tone = 0.25
start A
rule A {
  param t = uniform(0, 1)
  color (tone, 0, 0)
  box
  set tone = t
  split x { ~1: B | ~1: { set tone = tone * 0.5 B } }
  child C
}
rule B {
  color (tone, 0, 0)
  box
}
rule C {
  color (tone, 1, 0)
  box
}
)";

}  // namespace carried_attributes_test

using namespace carried_attributes_test;

TEST(CarriedAttributes, PiecesInlineCallsAndChildGenesInheritWhatWasSet) {
    const Grammar g = parseGrammar(kInherit, "inherit.grammar");
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const float t = test::startParam(g, c, "t");
        const Geometry geo = test::deriveComplete(g, c);
        ASSERT_EQ(geo.primitives.size(), 4u);
        std::vector<float> reds, child;
        for (const Appearance& a : geo.appearance) (a.color[1] == 1.0f ? child : reds).push_back(a.color[0]);
        std::sort(reds.begin(), reds.end());
        std::vector<float> expected = {0.25f, t, t * 0.5f};
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(reds, expected) << "seed " << seed;
        EXPECT_EQ(child, std::vector<float>{t}) << "seed " << seed;
    }
}

TEST(CarriedAttributes, ASetThatNothingReadsChangesNothing) {
    // the same grammar with and without sets: every primitive the same, in the same order
    const std::string base = test::readFile(test::sourcePath("grammars/spaceship.grammar"));
    std::string withSets = "carry unused = 1\n" + base;
    std::size_t at = 0;
    int inserted = 0;
    while ((at = withSets.find("\n  box", at)) != std::string::npos) {  // before every box of the file
        withSets.insert(at + 1, "  set unused = unused + 1\n");
        at += 30;
        ++inserted;
    }
    ASSERT_GT(inserted, 2);
    const Grammar plain = parseGrammar(base, "plain.grammar"), sets = parseGrammar(withSets, "sets.grammar");
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng{seed};
        const GenomeLimits limits{40};
        while (c.genes < 30 && grow(plain, c, rng, limits)) {
        }
        EXPECT_TRUE(test::identical(test::deriveComplete(plain, c), test::deriveComplete(sets, c))) << "seed " << seed;
    }
}

TEST(CarriedAttributes, TheMemoTellsSubtreesApartByWhatTheyInherit) {
    // C reads what A set, so two children with equal genes but different inherited tones differ
    const Grammar g = parseGrammar(kInherit, "inherit.grammar");
    DeriveScratch withMemo;
    withMemo.memo = std::make_unique<SubtreeMemo>(1u << 20);
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        for (int again = 0; again < 2; ++again) {
            Geometry geo;
            ASSERT_EQ(derive(g, c, geo, withMemo), DeriveStatus::Complete);
            EXPECT_TRUE(test::identical(geo, test::deriveComplete(g, c))) << "seed " << seed;
        }
    }
}

TEST(CarriedAttributes, ASubtreeDerivedFromItsStartReadsWhatItInherited) {
    const Grammar g = parseGrammar(kInherit, "inherit.grammar");
    Chromosome c;
    Rng rng{3};
    ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
    ASSERT_EQ(c.genes, 2u);
    DeriveScratch scratch;
    std::vector<SubtreeStart> starts;
    const std::uint32_t child = std::uint32_t(c.child(0, 0));  // offset from the root, at word 0
    ASSERT_EQ(findSubtreeStarts(g, c, child, scratch, starts), DeriveStatus::Complete);
    ASSERT_EQ(starts.size(), 1u);
    EXPECT_EQ(starts[0].carried[0], test::startParam(g, c, "t"));
    Geometry geo;
    ASSERT_EQ(deriveSubtree(g, c, child, starts[0], geo, scratch), DeriveStatus::Complete);
    ASSERT_EQ(geo.primitives.size(), 1u);
    EXPECT_EQ(geo.appearance[0].color[0], test::startParam(g, c, "t"));
}

TEST(CarriedAttributes, SentEntitiesKeepTheirValuesForTheGathersStepsAndRoutes) {
    const Grammar g = parseGrammar(R"(carry rank = 0
start S
rule S {
  param n = int(1, 12)
  param u = uniform(0, 1)
  size (12, 1, 1)
  repeat x count n {
    set rank = piece.index * 7 - 12 * floor(piece.index * 7 / 12)
    send items
  }
  gather items {
    shuffle u
    order by rank desc
    keep first 5 : { color (rank / 100, 0, 0) box } | rest : nil
  }
}
)", "ranks.grammar");
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Chromosome c;
        Rng rng{seed};
        ASSERT_TRUE(growUncontrolled(g, c, rng, 10));
        const int n = int(test::startParam(g, c, "n"));
        std::vector<float> ranks;
        for (int k = 0; k < n; ++k) ranks.push_back(float(k * 7 % 12));
        std::sort(ranks.begin(), ranks.end(), std::greater<float>());
        ranks.resize(std::min<std::size_t>(ranks.size(), 5));
        const Geometry geo = test::deriveComplete(g, c);
        ASSERT_EQ(geo.primitives.size(), ranks.size()) << "seed " << seed;
        for (std::size_t i = 0; i < ranks.size(); ++i) {
            EXPECT_EQ(geo.appearance[i].color[0], ranks[i] / 100.0f) << "seed " << seed;
            const float x = geo.primitives[i].centre.x;  // each box where its own piece was: rank says which
            const int piece = int(std::lround((x + 6.0f) / (12.0f / float(n)) - 0.5f));
            EXPECT_EQ(float(piece * 7 % 12), ranks[i]) << "seed " << seed;
        }
    }
}

}  // namespace shapevo
