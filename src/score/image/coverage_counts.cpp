// CoverageCounts: counting adds and subtracts one per pixel with a ripple through the bit
// planes, 64 pixels at a time, through every plane of the word's block (a carry or borrow of
// zero changes nothing; a loop that stopped at it would branch on the data).
#include "score/image/coverage_counts.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace shapevo {

namespace {
/// The change in covered, hit and avoided pixels of one add() or remove(), in registers: the
/// counts' words are written through pointers the compiler cannot tell from Delta's.
struct Tally {
    const std::uint64_t* hit;
    const std::uint64_t* avoid;
    std::int64_t covered = 0, hits = 0, avoided = 0;
    explicit Tally(const ImageTarget& t) : hit(t.hit.data()), avoid(t.avoid.data()) {}
    void count(std::uint64_t pixels, std::size_t i) {
        covered += std::popcount(pixels);
        hits += std::popcount(pixels & hit[i]);
        avoided += std::popcount(pixels & avoid[i]);
    }
    void addTo(CoverageCounts::Delta& delta, std::int64_t sign) const {
        delta.covered += sign * covered;
        delta.hit += sign * hits;
        delta.avoided += sign * avoided;
    }
};
}  // namespace

void CoverageCounts::overlay(const CoverageCounts& base) {
    if (base.base_) throw std::logic_error("CoverageCounts::overlay: the base is an overlay itself");
    layout_ = base.layout_;
    blocks_.assign(base.blocks_.size(), CoverageBlock());
    pool_ = base.pool_;
    base_ = &base;
}

void CoverageCounts::flatten() {
    if (!base_) return;
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        if (!blocks_[b]) blocks_[b] = base_->blocks_[b];
    base_ = nullptr;
}

const CoverageBlock& CoverageCounts::writable(std::size_t b) {
    CoverageBlock& p = blocks_[b];
    const CoverageBlock& from = blockAt(b);  // (an overlay's first write: the base's)
    if (!from) {
        p = CoverageBlock::make(pool_, 1, true);
    } else if (&from != &p || p.shared()) {
        CoverageBlock copy = CoverageBlock::make(pool_, from.planes(), false);
        std::memcpy(copy.cells(), from.cells(), kBlockWords * (1 + from.planes()) * sizeof(std::uint64_t));
        p = std::move(copy);
    }
    return p;
}

void CoverageCounts::grow(std::size_t b) {
    const CoverageBlock& old = blocks_[b];
    const std::uint32_t from = old.planes(), to = from + 1;
    if (to > CoverageBlock::kMaxPlanes) throw std::logic_error("CoverageCounts: a pixel covered more than 2^32 times");
    CoverageBlock block = CoverageBlock::make(pool_, to, false);
    for (std::size_t w = 0; w < kBlockWords; ++w) {
        std::memcpy(block.cell(w), old.cell(w), (1 + from) * sizeof(std::uint64_t));
        block.cell(w)[to] = 0;
    }
    blocks_[b] = std::move(block);
}

/// The blocks one add() or remove() writes, each made writable once: a primitive's rows cross the
/// same few tiles in turn, so the last few opened are remembered (a block written stays held by
/// this picture alone until the call returns).
class CoverageCounts::OpenBlocks {
public:
    struct Open {
        std::uint32_t block = UINT32_MAX, planes = 0;
        std::uint64_t* cells = nullptr;
        std::uint64_t* cell(std::uint32_t offset) const { return cells + std::size_t(offset) * (1 + planes); }
    };
    explicit OpenBlocks(CoverageCounts& counts) : counts_(counts) {}
    Open& open(std::uint32_t block) {
        if (open_[last_].block == block) return open_[last_];  // (mostly: the word before's block)
        for (unsigned k = 0; k < kOpen; ++k)
            if (open_[k].block == block) {
                last_ = k;
                return open_[k];
            }
        last_ = next_ % kOpen;
        Open& o = open_[next_++ % kOpen];
        const CoverageBlock& b = counts_.writable(block);
        o = {block, b.planes(), b.cells()};
        return o;
    }
    /// Give `o`'s block one more plane (all zero).
    void grow(Open& o) {
        counts_.grow(o.block);
        const CoverageBlock& b = counts_.blocks_[o.block];
        o.planes = b.planes();
        o.cells = b.cells();
    }

private:
    static constexpr unsigned kOpen = 4;
    CoverageCounts& counts_;
    Open open_[kOpen];
    unsigned next_ = 0, last_ = 0;
};

void CoverageCounts::add(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    OpenBlocks blocks(*this);
    Tally tally(target);
    for (const WordMask& m : words) {
        const CoverageLayout::Place place = layout_.place(m.index);
        OpenBlocks::Open& block = blocks.open(place.block);
        const std::uint32_t planes = block.planes;
        std::uint64_t* const c = block.cell(place.offset);
        const std::uint64_t mask = m.mask();
        tally.count(mask & ~c[0], m.index);
        c[0] |= mask;
        std::uint64_t carry = mask;
        for (std::uint32_t p = 1; p <= planes; ++p) {  // (every plane: no branch on the data)
            const std::uint64_t next = c[p] & carry;
            c[p] ^= carry;
            carry = next;
        }
        if (carry) {
            blocks.grow(block);
            block.cell(place.offset)[block.planes] = carry;
        }
    }
    tally.addTo(delta, 1);
}

void CoverageCounts::remove(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    OpenBlocks blocks(*this);
    Tally tally(target);
    for (const WordMask& m : words) {
        const CoverageLayout::Place place = layout_.place(m.index);
        const OpenBlocks::Open& block = blocks.open(place.block);
        const std::uint32_t planes = block.planes;
        std::uint64_t* const c = block.cell(place.offset);
        const std::uint64_t mask = m.mask();
        if (mask & ~c[0]) throw std::logic_error("CoverageCounts::remove: pixels that were not added");
        std::uint64_t borrow = mask, any = 0;
        for (std::uint32_t p = 1; p <= planes; ++p) {  // (every plane: no branch on the data)
            const std::uint64_t next = ~c[p] & borrow;
            c[p] ^= borrow;
            any |= c[p];
            borrow = next;
        }
        const std::uint64_t gone = mask & ~any;
        c[0] &= ~gone;
        tally.count(gone, m.index);
    }
    tally.addTo(delta, -1);
}

std::uint64_t CoverageCounts::covered(std::size_t i) const {
    const CoverageLayout::Place place = layout_.place(std::uint32_t(i));
    const CoverageBlock& p = blockAt(place.block);
    return p ? p.cell(place.offset)[0] : 0;
}

std::uint32_t CoverageCounts::count(std::size_t i, int bit) const {
    const CoverageLayout::Place place = layout_.place(std::uint32_t(i));
    const CoverageBlock& p = blockAt(place.block);
    if (!p) return 0;
    const std::uint64_t* c = p.cell(place.offset);
    std::uint32_t n = 0;
    for (std::uint32_t k = 0; k < p.planes(); ++k) n |= std::uint32_t(c[1 + k] >> bit & 1) << k;
    return n;
}

std::size_t CoverageCounts::bytes() const {
    std::size_t n = handleBytes();
    forEachBlock([&](const void*, std::size_t bytes) { n += bytes; });
    return n;
}

}  // namespace shapevo
