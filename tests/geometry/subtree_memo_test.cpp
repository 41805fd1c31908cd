// Incremental derivation (geometry/subtree_memo.hpp): with a memo, derive gives the very geometry
// and status it gives without one, for every shipped grammar, every operator's children, limits
// that truncate, a memo that wraps; children find their parents' unchanged subtrees; equal
// contents get equal numbers wherever they are, different contents different ones.
#include <gtest/gtest.h>

#include <cstring>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../model_stream.hpp"
#include "../small_tree_grammar.hpp"
#include "../geometry_compare.hpp"
#include "../test_support.hpp"
#include "genome/operators.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo {
namespace {

using test::identical;


/// Random models and a stream of their children by every operator (a GA's stream, in short).
std::vector<Chromosome> modelsAndChildren(const Grammar& g, std::size_t count, std::uint64_t seed) {
    Rng rng(seed);
    const GenomeLimits limits{120};
    std::vector<Chromosome> out;
    for (std::uint32_t i = 0; i < 6; ++i) {
        Chromosome c;
        growRandomLength(g, c, rng, limits, 3 + 4 * i, 3 + 8 * i);
        out.push_back(c);
    }
    test::appendChildren(g, out, count, rng, limits, 6, true);
    return out;
}

TEST(SubtreeMemo, DerivesEveryShippedGrammarsChildrenBitForBitAsWithout) {
    const std::vector<std::string> paths = test::shippedGrammarFiles();
    ASSERT_GE(paths.size(), 10u);
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        const Grammar g = loadGrammar(path);
        Geometry a, b;
        // As many models as take a moment: a rule file's one gene can make 100,000 primitives.
        DeriveScratch plain;
        derive(g, modelsAndChildren(g, 1, 5).front(), a, plain);
        const std::size_t count = std::clamp<std::size_t>(200000 / (a.primitives.size() + 1), 30, 600);
        // The smallest memo that holds one model's subtrees (else it turns itself off), so that
        // its rings wrap over the models: 1 MB, or 4 MB for models as large as a building's.
        bool held = false;
        for (const std::size_t bytes : {std::size_t(1) << 20, std::size_t(4) << 20}) {
            DeriveScratch memoized;
            memoized.memo = std::make_unique<SubtreeMemo>(bytes);
            std::uint32_t mostGenes = 0;
            for (const Chromosome& c : modelsAndChildren(g, count, 5)) {
                const DeriveStatus sa = derive(g, c, a, plain), sb = derive(g, c, b, memoized);
                ASSERT_EQ(int(sa), int(sb));
                ASSERT_TRUE(identical(a, b));
                mostGenes = std::max(mostGenes, c.genes);
            }
            const SubtreeMemo::Stats& st = memoized.memo->stats();
            if (st.outgrown) continue;
            // Children share subtrees: every gene's but the root's (some rule files make one gene).
            if (g.textures.empty() && mostGenes > 3) EXPECT_GT(st.hits, 25u);
            held = true;
            break;
        }
        EXPECT_TRUE(held) << "a 4 MB memo holds no model of this grammar";
    }
}

TEST(SubtreeMemo, PrimitiveAndTaskLimitsStopWhereTheyStopWithout) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    DeriveScratch plain, memoized;
    memoized.memo = std::make_unique<SubtreeMemo>(4 << 20);
    Geometry a, b;
    int truncated = 0;
    const std::vector<Chromosome> models = modelsAndChildren(g, 400, 9);
    for (std::size_t limit : {1, 2, 3, 5, 8, 13, 40}) {
        for (const Chromosome& c : models) {
            const DeriveStatus sa = derive(g, c, a, plain, limit), sb = derive(g, c, b, memoized, limit);
            ASSERT_EQ(int(sa), int(sb)) << "limit " << limit;
            ASSERT_TRUE(identical(a, b)) << "limit " << limit;
            truncated += sa == DeriveStatus::Truncated;
        }
        // and with no limit in between: what was kept under a limit is whole
        for (std::size_t i = 0; i < models.size(); i += 7) {
            derive(g, models[i], a, plain);
            derive(g, models[i], b, memoized);
            ASSERT_TRUE(identical(a, b));
        }
    }
    EXPECT_GT(truncated, 500);
}

TEST(SubtreeMemo, ASubtreeKeptUnderNoLimitIsNotReusedWhereItsTasksWouldPassTheLimit) {
    // Mirrors without boxes: eight tasks per gene and no primitive, so the task limit
    // (4 * maxPrimitives + 1,024) stops the chain, not the primitive limit.
    const Grammar g = parseGrammar(R"(
start A
rule A {
  param x = uniform(0, 1)
  child A prob 0.99
  mirror x
  mirror y
  mirror z
}
)", "chain.grammar");
    Rng rng(4);
    Chromosome c;
    growRandomLength(g, c, rng, GenomeLimits{400}, 300, 300);
    ASSERT_EQ(c.genes, 300u);
    DeriveScratch plain, memoized;
    memoized.memo = std::make_unique<SubtreeMemo>(8 << 20);
    Geometry a, b;
    ASSERT_EQ(int(derive(g, c, b, memoized, 100000)), int(DeriveStatus::Complete));  // kept whole
    for (std::size_t limit : {1, 50, 100000}) {
        const DeriveStatus sa = derive(g, c, a, plain, limit), sb = derive(g, c, b, memoized, limit);
        EXPECT_EQ(int(sa), int(sb)) << "limit " << limit;
        EXPECT_EQ(int(sa), int(limit < 1000 ? DeriveStatus::Truncated : DeriveStatus::Complete)) << "limit " << limit;
    }
}

TEST(SubtreeMemo, AChildFindsItsParentsUnchangedSubtrees) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    Rng rng(3);
    Chromosome parent;
    growRandomLength(g, parent, rng, GenomeLimits{200}, 60, 60);
    DeriveScratch scratch;
    scratch.memo = std::make_unique<SubtreeMemo>(8 << 20);
    Geometry geometry;
    derive(g, parent, geometry, scratch);
    const SubtreeMemo::Stats first = scratch.memo->stats();
    EXPECT_EQ(first.hits, 0u);
    EXPECT_EQ(first.stored, parent.genes - 1);  // one subtree per gene but the root (a whole model)

    derive(g, parent, geometry, scratch);  // the same model: the root's children's subtrees at once
    EXPECT_GT(scratch.memo->stats().hits, 0u);
    EXPECT_LE(scratch.memo->stats().hits, 3u);
    EXPECT_EQ(scratch.memo->stats().stored, first.stored);

    Chromosome child = parent;
    ASSERT_TRUE(alter(g, child, rng));
    const SubtreeMemo::Stats before = scratch.memo->stats();
    derive(g, child, geometry, scratch);
    const SubtreeMemo::Stats after = scratch.memo->stats();
    // Only the altered gene and its ancestors are derived; everything hanging off them is found.
    EXPECT_GT(after.hits, before.hits);
    EXPECT_LT(after.stored - before.stored, 30u);
}

TEST(SubtreeMemo, AMemoTurnedOffIsNeitherAskedNorFilled) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    const std::vector<Chromosome> models = modelsAndChildren(g, 50, 2);
    DeriveScratch plain, memoized;
    memoized.memo = std::make_unique<SubtreeMemo>(4 << 20);
    Geometry a, b;
    for (const Chromosome& c : models) derive(g, c, b, memoized);
    const SubtreeMemo::Stats before = memoized.memo->stats();
    ASSERT_GT(before.stored, 0u);
    memoized.memo->turnOff();
    for (const Chromosome& c : models) {
        derive(g, c, a, plain);
        derive(g, c, b, memoized);
        ASSERT_TRUE(identical(a, b));
        EXPECT_TRUE(memoized.reused.empty());
    }
    EXPECT_EQ(memoized.memo->stats().hits + memoized.memo->stats().misses, before.hits + before.misses);
    EXPECT_EQ(memoized.memo->stats().stored, before.stored);
}

TEST(SubtreeMemo, AModelWhoseSubtreesOutgrowTheMemoTurnsItOffAndDerivesTheSame) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    Rng rng(8);
    Chromosome small, large;
    growRandomLength(g, small, rng, GenomeLimits{200}, 20, 20);
    growRandomLength(g, large, rng, GenomeLimits{3000}, 2000, 2000);
    DeriveScratch plain, memoized;
    memoized.memo = std::make_unique<SubtreeMemo>(256 << 10);  // outputs: ~48,000 words
    Geometry a, b;
    for (int i = 0; i < 3; ++i) derive(g, small, b, memoized);
    EXPECT_TRUE(memoized.memo->on());  // a small model fits: kept and found
    EXPECT_GT(memoized.memo->stats().hits, 0u);
    EXPECT_FALSE(memoized.memo->stats().outgrown);

    derive(g, large, a, plain);
    derive(g, large, b, memoized);  // every primitive once per ancestor: more than the ring holds
    ASSERT_TRUE(identical(a, b));
    EXPECT_TRUE(memoized.memo->stats().outgrown);
    EXPECT_FALSE(memoized.memo->on());
    const SubtreeMemo::Stats after = memoized.memo->stats();
    derive(g, large, b, memoized);  // off for good: neither asked nor filled
    ASSERT_TRUE(identical(a, b));
    EXPECT_EQ(memoized.memo->stats().hits + memoized.memo->stats().misses, after.hits + after.misses);
}

TEST(SubtreeMemo, ChildrenInCopiesOfOneScopeThatReadPieceIndexAreNotConfused) {
    // `copy` gives every piece the same scope, so the child B of each copy starts on the same
    // scope with the same content: only its piece place (piece.index) tells the starts apart.
    const Grammar g = parseGrammar(R"(
start A
rule A {
  param n = int(1, 4)
  copy n + 1 { child B }
}
rule B {
  param h = uniform(1, 2)
  translate (piece.index * 2, 0, 0)
  size (1, h * (piece.index + 1), 1)
  box
  child B prob 0.5
}
)", "copies.grammar");
    DeriveScratch plain, memoized;
    memoized.memo = std::make_unique<SubtreeMemo>(4 << 20);
    Geometry a, b;
    for (const Chromosome& c : modelsAndChildren(g, 200, 11)) {
        ASSERT_EQ(int(derive(g, c, a, plain)), int(derive(g, c, b, memoized)));
        ASSERT_TRUE(identical(a, b));
    }
    EXPECT_GT(memoized.memo->stats().hits, 50u);
    // findSubtreeStarts names each copy's start by its place; deriving from it gives that copy's boxes.
    Rng rng(2);
    Chromosome c;
    growRandomLength(g, c, rng, GenomeLimits{40}, 6, 12);
    derive(g, c, a, plain);
    const auto b0 = std::uint32_t(c.child(0, 0));
    ASSERT_GT(b0, 0u);
    std::vector<SubtreeStart> starts;
    ASSERT_EQ(findSubtreeStarts(g, c, b0, plain, starts), DeriveStatus::Complete);
    ASSERT_GE(starts.size(), 2u);
    for (std::size_t k = 0; k < starts.size(); ++k) {
        EXPECT_EQ(starts[k].place, piecePlace(std::uint32_t(k), std::uint32_t(starts.size())));
        ASSERT_EQ(deriveSubtree(g, c, b0, starts[k], b, plain), DeriveStatus::Complete);
        ASSERT_FALSE(b.primitives.empty());
        EXPECT_EQ(b.primitives[0].centre.x, float(k) * 2.0f) << "copy " << k << " read its own piece.index";
    }
}

TEST(SubtreeMemo, EqualContentsShareANumberWhereverTheyAreAndOthersDoNot) {
    const Grammar g = parseGrammar(test::kSmallTree, "tree.grammar");
    Rng rng(21);
    Chromosome a;
    growRandomLength(g, a, rng, GenomeLimits{200}, 40, 40);
    SubtreeMemo memo(8 << 20);
    memo.identify(g, a);
    const std::uint64_t root = memo.contentOf(0);
    std::vector<std::uint64_t> numbers;
    for (std::uint32_t pos = 0; pos < a.size(); pos += g.rules[a.rule(pos)].geneWords()) numbers.push_back(memo.contentOf(pos));
    std::sort(numbers.begin(), numbers.end());
    // Random parameters: no two subtrees of one tree are equal.
    EXPECT_EQ(std::unique(numbers.begin(), numbers.end()), numbers.end());

    memo.identify(g, a);  // seen before: the same numbers
    EXPECT_EQ(memo.contentOf(0), root);

    Chromosome b = a;
    std::uint32_t gene = 0;
    while (g.rules[b.rule(gene)].paramFloats == 0) gene += g.rules[b.rule(gene)].geneWords();
    const Rule& r = g.rules[b.rule(gene)];
    const std::uint64_t before = memo.contentOf(gene);
    b.setParam(gene, r, 0, std::nextafter(b.param(gene, r, 0), 10.0f));  // one bit of one parameter
    memo.identify(g, b);
    EXPECT_NE(memo.contentOf(gene), before);
    EXPECT_NE(memo.contentOf(0), root);  // and the root's content holds it
    EXPECT_GT(memo.contentOf(0), numbers.back());  // a new content: a number never given before
}

}  // namespace
}  // namespace shapevo
