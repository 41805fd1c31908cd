// CoverageCounts: how many primitives cover each pixel of a picture, so that a child can start
// from its parent's picture, take away the primitives its operator replaced and add the new
// ones, without drawing the rest (incremental evaluation, score/model_state.hpp).
//
// Layout: per 64-pixel word of the picture, the counts as bit planes (plane p holds bit p of the
// 64 counts) after one plane of the pixels whose count is above zero; words in blocks of
// kBlockWords, each block with as many planes as its largest count needs. A block no primitive
// touched is absent (all zero).
//
// Promises:
//  - Exact: after add()s and remove()s (each remove() of one primitive's words that an add()
//    put in and no remove() took out yet), covered(i) is the OR of the words present, and each
//    call adds to `Delta` the change in covered, hit and avoided pixels against the target.
//  - Shared: a copy holds its blocks by reference; add() and remove() copy a block only when it
//    is shared and written to, so a child that changes a few primitives copies a few blocks.
//    Copies may be read and written on different threads (each written by one thread).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "score/image_target.hpp"
#include "score/silhouette_raster.hpp"

namespace shapevo {

class CoverageCounts {
public:
    static constexpr std::size_t kBlockWords = 128;
    struct Delta {
        std::int64_t covered = 0, hit = 0, avoided = 0;
    };

    CoverageCounts() = default;
    /// A picture of `words` 64-pixel words, all zero.
    explicit CoverageCounts(std::size_t words) : blocks_((words + kBlockWords - 1) / kBlockWords) {}

    /// One primitive's words (SilhouetteRaster::wordMasks: each word index at most once).
    void add(std::span<const WordMask> words, const ImageTarget& target, Delta& delta);
    /// Take out one primitive's words, put in by add() before.
    void remove(std::span<const WordMask> words, const ImageTarget& target, Delta& delta);

    /// The pixels of word `i` with a count above zero.
    std::uint64_t covered(std::size_t i) const;
    /// The count of pixel `bit` of word `i` (for tests).
    std::uint32_t count(std::size_t i, int bit) const;
    /// Bytes of the blocks it holds (shared ones included whole).
    std::size_t bytes() const;
    std::size_t words() const { return blocks_.size() * kBlockWords; }
    /// Call f(key, bytes) for every block it holds: equal keys are one block shared (memory counts).
    template <class F>
    void forEachBlock(F&& f) const {
        for (const auto& p : blocks_)
            if (p) f(static_cast<const void*>(p.get()), (2 + kBlockWords * (1 + planesOf(p))) * sizeof(std::uint64_t));
    }

private:
    /// A block: word 0 its plane count P, then per word of the picture 1 + P words (the
    /// above-zero plane, then the planes), in one allocation.
    using Block = std::shared_ptr<std::uint64_t[]>;
    static std::uint32_t planesOf(const Block& b) { return std::uint32_t(b[0]); }
    static std::uint64_t* cell(const Block& b, std::size_t w) { return b.get() + 1 + w * (1 + planesOf(b)); }
    static Block makeBlock(std::uint32_t planes);
    /// Block `b`, made or copied so that only this picture holds it.
    std::uint64_t* writable(std::size_t b);
    /// Give block `b` (held only here) one more plane (all zero).
    void grow(std::size_t b);

    std::vector<Block> blocks_;
};

}  // namespace shapevo
