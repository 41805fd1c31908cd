// CoverageCounts: how many primitives cover each pixel of a picture, so that a child can start
// from its parent's picture, take away the primitives its operator replaced and add the new
// ones, without drawing the rest (incremental evaluation: score/image_model.hpp holds a model's
// coverage, score/image_from_parent.cpp scores a child from it).
//
// Layout: per 64-pixel word of the picture, the counts as bit planes (plane p holds bit p of the
// 64 counts) after one plane of the pixels whose count is above zero; words in blocks of
// kBlockWords (score/image/coverage_block.hpp), tiles of the picture (score/image/coverage_layout.hpp), each
// block with as many planes as its largest count needs. A block no primitive touched is absent (all zero).
//
// Promises:
//  - Exact: after add()s and remove()s (each remove() of one primitive's words that an add()
//    put in and no remove() took out yet), covered(i) is the OR of the words present, and each
//    call adds to `Delta` the change in covered, hit and avoided pixels against the target.
//  - Shared: a copy holds its blocks by reference; add() and remove() copy a block only when it
//    is shared and written to, so a child that changes a few primitives copies a few blocks.
//    Copies may be read and written on different threads (each written by one thread).
//  - Pooled: with a CoverageBlockPool, every block comes from it and goes back to it, and a
//    copy assigned over another keeps that one's capacity (no allocation once warm).
//  - Overlaid: overlay(base) makes a picture equal to `base` that holds none of base's blocks
//    (no reference is taken on them, so nothing of base is touched until written): a block is
//    copied from base when first written, read from base until then. `base` must outlive the
//    overlay and not change; flatten() then takes references on the blocks still read from it,
//    after which base may go.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "score/image/coverage_block.hpp"
#include "score/image/coverage_layout.hpp"
#include "score/image/image_target.hpp"
#include "score/image/silhouette_raster.hpp"

namespace shapevo {

class CoverageCounts {
public:
    static constexpr std::size_t kBlockWords = CoverageBlock::kPictureWords;
    struct Delta {
        std::int64_t covered = 0, hit = 0, avoided = 0;
    };

    CoverageCounts() = default;
    /// A picture laid out as `layout`, all zero, its blocks from `pool` (null: the heap).
    explicit CoverageCounts(const CoverageLayout& layout, CoverageBlockPool* pool = nullptr)
        : layout_(layout), blocks_(layout.blocks()), pool_(pool) {}
    /// All zero again: laid out as `layout`, blocks from `pool`, keeping the capacity.
    void reset(const CoverageLayout& layout, CoverageBlockPool* pool) {
        layout_ = layout;
        blocks_.assign(layout.blocks(), CoverageBlock());
        pool_ = pool;
        base_ = nullptr;
    }
    /// Equal to `base` (which must not be an overlay itself), holding none of its blocks yet.
    void overlay(const CoverageCounts& base);
    /// Hold every block itself (the ones still read from the base by reference): no base after.
    void flatten();
    bool overlaid() const { return base_ != nullptr; }
    /// Hold no blocks, keeping the capacity.
    void clear() {
        blocks_.clear();
        base_ = nullptr;
    }
    /// Ask for its block handles (a hint: nothing changes).
    void prefetchHandles() const {
        const char* const first = reinterpret_cast<const char*>(blocks_.data());
        for (std::size_t at = 0; at < blocks_.size() * sizeof(CoverageBlock); at += 64) __builtin_prefetch(first + at);
    }
    /// Bytes of its block handles (their capacity).
    std::size_t handleBytes() const { return blocks_.capacity() * sizeof(CoverageBlock); }

    /// One primitive's words (SilhouetteRaster::wordMasks: each word index at most once).
    void add(std::span<const WordMask> words, const ImageTarget& target, Delta& delta);
    /// Take out one primitive's words, put in by add() before.
    void remove(std::span<const WordMask> words, const ImageTarget& target, Delta& delta);

    /// The pixels of word `i` with a count above zero.
    std::uint64_t covered(std::size_t i) const;
    /// The count of pixel `bit` of word `i` (for tests).
    std::uint32_t count(std::size_t i, int bit) const;
    /// Bytes of its handles and of the blocks it holds (shared ones included whole).
    std::size_t bytes() const;
    /// Call f(key, bytes) for every block it holds (an overlay: its own, not its base's): equal
    /// keys are one block shared (memory counts).
    template <class F>
    void forEachBlock(F&& f) const {
        for (const CoverageBlock& b : blocks_)
            if (b) f(b.key(), b.bytes());
    }

private:
    class OpenBlocks;
    /// Block `b`, made or copied so that only this picture holds it.
    const CoverageBlock& writable(std::size_t b);
    /// Give block `b` (held only here) one more plane (all zero).
    void grow(std::size_t b);

    /// Block `b` as read: its own, or its base's.
    const CoverageBlock& blockAt(std::size_t b) const { return blocks_[b] || !base_ ? blocks_[b] : base_->blocks_[b]; }

    CoverageLayout layout_;
    std::vector<CoverageBlock> blocks_;
    CoverageBlockPool* pool_ = nullptr;
    const CoverageCounts* base_ = nullptr;  ///< an overlay's base (null: none)
};

}  // namespace shapevo
