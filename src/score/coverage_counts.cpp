// CoverageCounts: counting adds and subtracts one per pixel with a ripple through the bit
// planes, 64 pixels at a time; it stops at the first plane with no carry (or borrow) left.
#include "score/coverage_counts.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace shapevo {

namespace {
void tally(CoverageCounts::Delta& delta, std::int64_t sign, std::uint64_t pixels, std::size_t i, const ImageTarget& t) {
    delta.covered += sign * std::popcount(pixels);
    delta.hit += sign * std::popcount(pixels & t.hit[i]);
    delta.avoided += sign * std::popcount(pixels & t.avoid[i]);
}
}  // namespace

void CoverageCounts::overlay(const CoverageCounts& base) {
    if (base.base_) throw std::logic_error("CoverageCounts::overlay: the base is an overlay itself");
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

void CoverageCounts::add(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    std::size_t at = SIZE_MAX;  // the block being written (words come mostly in order)
    std::uint64_t* block = nullptr;
    std::uint32_t planes = 0;
    for (const WordMask& m : words) {
        if (m.index / kBlockWords != at) {
            at = m.index / kBlockWords;
            const CoverageBlock& b = writable(at);
            block = b.cells();
            planes = b.planes();
        }
        const std::size_t w = m.index % kBlockWords;
        std::uint64_t* c = block + w * (1 + planes);
        const std::uint64_t mask = m.mask();
        tally(delta, 1, mask & ~c[0], m.index, target);
        c[0] |= mask;
        std::uint64_t carry = mask;
        for (std::uint32_t p = 1; p <= planes && carry; ++p) {
            const std::uint64_t next = c[p] & carry;
            c[p] ^= carry;
            carry = next;
        }
        if (carry) {
            grow(at);
            block = blocks_[at].cells();
            planes = blocks_[at].planes();
            block[w * (1 + planes) + planes] = carry;
        }
    }
}

void CoverageCounts::remove(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    std::size_t at = SIZE_MAX;
    std::uint64_t* block = nullptr;
    std::uint32_t planes = 0;
    for (const WordMask& m : words) {
        if (m.index / kBlockWords != at) {
            at = m.index / kBlockWords;
            const CoverageBlock& b = writable(at);
            block = b.cells();
            planes = b.planes();
        }
        std::uint64_t* c = block + (m.index % kBlockWords) * (1 + planes);
        const std::uint64_t mask = m.mask();
        if (mask & ~c[0]) throw std::logic_error("CoverageCounts::remove: pixels that were not added");
        std::uint64_t borrow = mask, any = 0;
        std::uint32_t p = 1;
        for (; p <= planes && borrow; ++p) {
            const std::uint64_t next = ~c[p] & borrow;
            c[p] ^= borrow;
            any |= c[p];
            borrow = next;
        }
        for (; p <= planes; ++p) any |= c[p];
        const std::uint64_t gone = mask & ~any;
        c[0] &= ~gone;
        tally(delta, -1, gone, m.index, target);
    }
}

std::uint64_t CoverageCounts::covered(std::size_t i) const {
    const CoverageBlock& p = blockAt(i / kBlockWords);
    return p ? p.cell(i % kBlockWords)[0] : 0;
}

std::uint32_t CoverageCounts::count(std::size_t i, int bit) const {
    const CoverageBlock& p = blockAt(i / kBlockWords);
    if (!p) return 0;
    const std::uint64_t* c = p.cell(i % kBlockWords);
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
