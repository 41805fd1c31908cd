// CoverageCounts (score/image/coverage_counts.hpp): per-pixel counts as bit planes agree with a
// brute-force count per pixel after random adds and removes, the deltas with brute-force
// popcounts against the target, and a copy is not changed by writes to the picture it was
// copied from (nor the other way round); blocks from a pool go back to it and come out again
// without stale pixels; the tiles of CoverageLayout place every word of a picture in a cell of
// its own, as a division would.
#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "genome/random.hpp"
#include "score/image/coverage_counts.hpp"

namespace shapevo {
namespace {

constexpr std::size_t kWords = 700;  // 4 words a row, 175 rows: tiles 2 words wide, the last ones cut short
const CoverageLayout kLayout(4, 175);

ImageTarget countingTarget(Rng& rng) {
    ImageTarget t;
    t.width = 256;
    t.height = 175;
    t.hit.resize(kWords);
    t.avoid.resize(kWords);
    for (std::size_t i = 0; i < kWords; ++i) {
        t.hit[i] = rng.next();
        t.avoid[i] = rng.next() & ~t.hit[i];
    }
    return t;
}

/// One primitive's words: distinct indices in increasing order, random masks.
std::vector<WordMask> randomWords(Rng& rng) {
    std::vector<WordMask> words;
    // A third of them pile up on the first words, so that counts grow deep there.
    const std::size_t first = rng.below(3) == 0 ? rng.below(8) : rng.below(kWords), n = 1 + rng.below(40);
    for (std::size_t i = first; i < kWords && i < first + n; i += 1 + rng.below(3)) {
        std::uint64_t m = rng.next() & rng.next();  // sparse-ish: counts stay varied
        if (rng.below(4) == 0) m = ~std::uint64_t(0);  // and some deep piles
        if (m == 0) m = 1;
        words.push_back({std::uint32_t(i), std::uint32_t(m), std::uint32_t(m >> 32)});
    }
    return words;
}

struct Brute {
    std::vector<std::uint32_t> counts = std::vector<std::uint32_t>(kWords * 64, 0);
    std::uint64_t covered(std::size_t i) const {
        std::uint64_t m = 0;
        for (int b = 0; b < 64; ++b) m |= std::uint64_t(counts[i * 64 + std::size_t(b)] > 0) << b;
        return m;
    }
    void apply(const std::vector<WordMask>& words, int sign) {
        for (const WordMask& w : words)
            for (int b = 0; b < 64; ++b)
                if (w.mask() >> b & 1) counts[w.index * 64 + std::size_t(b)] += std::uint32_t(sign);
    }
    CoverageCounts::Delta totals(const ImageTarget& t) const {
        CoverageCounts::Delta d;
        for (std::size_t i = 0; i < kWords; ++i) {
            const std::uint64_t m = covered(i);
            d.covered += std::popcount(m);
            d.hit += std::popcount(m & t.hit[i]);
            d.avoided += std::popcount(m & t.avoid[i]);
        }
        return d;
    }
};

/// Counts kept both ways, with the deltas CoverageCounts reports.
struct Tracked {
    explicit Tracked(CoverageBlockPool* pool = nullptr) : counts(kLayout, pool) {}
    CoverageCounts counts;
    Brute brute;
    CoverageCounts::Delta delta;
    void add(const std::vector<WordMask>& words, const ImageTarget& t) {
        counts.add(words, t, delta);
        brute.apply(words, 1);
    }
    void remove(const std::vector<WordMask>& words, const ImageTarget& t) {
        counts.remove(words, t, delta);
        brute.apply(words, -1);
    }
};

void expectSame(const CoverageCounts& c, const Brute& b) {
    for (std::size_t i = 0; i < kWords; ++i) {
        ASSERT_EQ(c.covered(i), b.covered(i)) << "word " << i;
        for (int bit = 0; bit < 64; bit += 7) ASSERT_EQ(c.count(i, bit), b.counts[i * 64 + std::size_t(bit)]);
    }
}

TEST(CoverageCounts, AddsAndRemovesAgreeWithABruteForceCountPerPixel) {
    Rng rng(11);
    const ImageTarget target = countingTarget(rng);
    Tracked t;
    std::vector<std::vector<WordMask>> present;
    for (int step = 0; step < 3000; ++step) {
        if (present.empty() || rng.below(5) < 3) {
            present.push_back(randomWords(rng));
            t.add(present.back(), target);
        } else {
            const std::size_t k = rng.below(present.size());
            t.remove(present[k], target);
            present.erase(present.begin() + std::ptrdiff_t(k));
        }
        if (step % 97 == 0) expectSame(t.counts, t.brute);
        const CoverageCounts::Delta want = t.brute.totals(target);
        ASSERT_EQ(t.delta.covered, want.covered) << "step " << step;
        ASSERT_EQ(t.delta.hit, want.hit);
        ASSERT_EQ(t.delta.avoided, want.avoided);
    }
    expectSame(t.counts, t.brute);
    std::size_t deepest = 0;
    for (std::uint32_t n : t.brute.counts) deepest = std::max<std::size_t>(deepest, n);
    EXPECT_GT(deepest, 32u);  // carries rippled through six planes and more
}

/// A parent of 200 random primitives and a child that shares its blocks and swaps 20 of them,
/// then the parent goes on: each checked after the other wrote.
void parentAndChild(Rng& rng, const ImageTarget& target, CoverageBlockPool* pool) {
    Tracked parent(pool);
    std::vector<std::vector<WordMask>> added;
    for (int k = 0; k < 200; ++k) {
        added.push_back(randomWords(rng));
        parent.add(added.back(), target);
    }
    Tracked child = parent;  // shares the parent's blocks
    for (int k = 0; k < 20; ++k) {  // the child takes out some, puts in others
        child.remove(added[std::size_t(k)], target);
        child.add(randomWords(rng), target);
    }
    expectSame(parent.counts, parent.brute);
    expectSame(child.counts, child.brute);
    parent.add(randomWords(rng), target);  // and the parent goes on without touching the child
    expectSame(child.counts, child.brute);
    expectSame(parent.counts, parent.brute);
    EXPECT_EQ(child.delta.covered, child.brute.totals(target).covered);
}

TEST(CoverageCounts, ACopyKeepsItsPixelsWhileTheOriginalChangesAndTheOtherWayRound) {
    Rng rng(3);
    parentAndChild(rng, countingTarget(rng), nullptr);
}

TEST(CoverageCounts, AnOverlayReadsItsBaseCopiesOnlyWhatItWritesAndOutlivesItOnceFlat) {
    Rng rng(9);
    const ImageTarget target = countingTarget(rng);
    CoverageBlockPool pool(64 << 20);
    Tracked child(&pool);
    {
        Tracked parent(&pool);
        std::vector<std::vector<WordMask>> added;
        for (int k = 0; k < 200; ++k) {
            added.push_back(randomWords(rng));
            parent.add(added.back(), target);
        }
        const std::size_t parentBytes = pool.bytesInUse();
        child.counts.overlay(parent.counts);  // equal to the parent, holding nothing
        child.brute = parent.brute;
        child.delta = parent.delta;
        EXPECT_TRUE(child.counts.overlaid());
        expectSame(child.counts, child.brute);
        EXPECT_EQ(pool.bytesInUse(), parentBytes);
        child.remove(added[3], target);
        child.add(randomWords(rng), target);
        expectSame(child.counts, child.brute);
        expectSame(parent.counts, parent.brute);  // the parent's blocks were copied, not written
        EXPECT_GT(pool.bytesInUse(), parentBytes);
        std::size_t own = 0;
        child.counts.forEachBlock([&](const void*, std::size_t) { ++own; });
        EXPECT_LT(own, kLayout.blocks());  // only the blocks it wrote
        child.counts.flatten();
        EXPECT_FALSE(child.counts.overlaid());
    }  // the parent goes
    expectSame(child.counts, child.brute);
    EXPECT_EQ(child.delta.covered, child.brute.totals(target).covered);
}

TEST(CoverageCounts, BlocksFromAPoolGoBackAndComeOutAgainWithoutStalePixels) {
    Rng rng(5);
    const ImageTarget target = countingTarget(rng);
    CoverageBlockPool pool(64 << 20);
    parentAndChild(rng, target, &pool);
    EXPECT_EQ(pool.bytesInUse(), 0u);  // every block came back...
    const std::size_t kept = pool.bytesKept();
    EXPECT_GT(kept, 0u);  // ...and is kept for reuse
    // Other primitives on blocks that still hold the first pictures' pixels: counted as new.
    std::size_t inUse = 0;
    {
        Tracked t(&pool);
        for (int k = 0; k < 300; ++k) t.add(randomWords(rng), target);
        expectSame(t.counts, t.brute);
        inUse = pool.bytesInUse();
        EXPECT_EQ(t.delta.covered, t.brute.totals(target).covered);
    }
    EXPECT_GT(inUse, 0u);
    EXPECT_LT(pool.bytesKept(), kept + inUse);  // some blocks were reused, not all made anew
    parentAndChild(rng, target, &pool);
    EXPECT_EQ(pool.bytesInUse(), 0u);
}

TEST(CoverageCounts, APoolKeepsNoMoreThanItsBound) {
    Rng rng(8);
    const ImageTarget target = countingTarget(rng);
    CoverageBlockPool pool(10000);  // a few blocks
    parentAndChild(rng, target, &pool);
    EXPECT_EQ(pool.bytesInUse(), 0u);
    EXPECT_LE(pool.bytesKept(), 10000u);
}

/// Where a word goes, by division: tiles kTileWords wide (as wide as the picture if narrower,
/// rounded up to a power of two) and kBlockWords / that many rows tall.
CoverageLayout::Place placeByDivision(std::uint64_t wordsPerRow, std::uint64_t i) {
    std::uint64_t tileWords = 1;
    while (tileWords < wordsPerRow && tileWords < CoverageLayout::kTileWords) tileWords *= 2;
    const std::uint64_t tileRows = CoverageLayout::kBlockWords / tileWords, tilesPerRow = (wordsPerRow + tileWords - 1) / tileWords;
    const std::uint64_t row = i / wordsPerRow, col = i % wordsPerRow;
    return {std::uint32_t(row / tileRows * tilesPerRow + col / tileWords), std::uint32_t(row % tileRows * tileWords + col % tileWords)};
}

TEST(CoverageLayout, PlacesEveryWordOfAPictureInItsOwnCellOfATile) {
    for (const std::uint32_t wordsPerRow : {1u, 2u, 3u, 4u, 13u, 64u, 4096u})
        for (const std::uint32_t rows : {1u, 2u, 63u, 64u, 65u, 130u, 600u}) {
            const CoverageLayout layout(wordsPerRow, rows);
            std::vector<std::uint8_t> used(layout.blocks() * CoverageLayout::kBlockWords, 0);
            for (std::uint32_t i = 0; i < layout.words(); ++i) {
                const CoverageLayout::Place p = layout.place(i), want = placeByDivision(wordsPerRow, i);
                ASSERT_EQ(p.block, want.block) << wordsPerRow << " x " << rows << " word " << i;
                ASSERT_EQ(p.offset, want.offset) << wordsPerRow << " x " << rows << " word " << i;
                ASSERT_LT(p.block, layout.blocks());
                ASSERT_EQ(used[p.block * CoverageLayout::kBlockWords + p.offset]++, 0) << "two words in one cell";
            }
        }
    // The largest picture it takes: the division by a multiplication stays exact to the last word.
    const CoverageLayout large(4096, 65536);
    for (std::uint64_t i = 0; i < large.words(); i += 999'983) {
        const std::uint32_t k = std::uint32_t(i);
        ASSERT_EQ(large.place(k).block, placeByDivision(4096, k).block) << k;
        ASSERT_EQ(large.place(k).offset, placeByDivision(4096, k).offset) << k;
    }
    EXPECT_EQ(large.place(std::uint32_t(large.words() - 1)).block, large.blocks() - 1);
    EXPECT_THROW(CoverageLayout(4097, 1), std::logic_error);
    EXPECT_THROW(CoverageLayout(1, 65537), std::logic_error);
}

TEST(CoverageCounts, RemovingPixelsNeverAddedIsAProgrammingError) {
    Rng rng(1);
    const ImageTarget target = countingTarget(rng);
    CoverageCounts counts(kLayout);
    CoverageCounts::Delta delta;
    const std::vector<WordMask> words{{5, 1, 0}};
    EXPECT_THROW(counts.remove(words, target, delta), std::logic_error);
}

}  // namespace
}  // namespace shapevo
