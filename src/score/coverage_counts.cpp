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

CoverageCounts::Block CoverageCounts::makeBlock(std::uint32_t planes) {
    Block b = std::make_shared<std::uint64_t[]>(1 + kBlockWords * (1 + planes));  // zeroed
    b[0] = planes;
    return b;
}

std::uint64_t* CoverageCounts::writable(std::size_t b) {
    Block& p = blocks_[b];
    if (!p) {
        p = makeBlock(1);
    } else if (p.use_count() > 1) {
        Block copy = std::make_shared_for_overwrite<std::uint64_t[]>(1 + kBlockWords * (1 + planesOf(p)));
        std::memcpy(copy.get(), p.get(), (1 + kBlockWords * (1 + planesOf(p))) * sizeof(std::uint64_t));
        p = std::move(copy);
    }
    return p.get();
}

void CoverageCounts::grow(std::size_t b) {
    const Block& old = blocks_[b];
    const std::uint32_t from = planesOf(old), to = from + 1;
    if (to > 32) throw std::logic_error("CoverageCounts: a pixel covered more than 2^32 times");
    Block block = makeBlock(to);
    for (std::size_t w = 0; w < kBlockWords; ++w)
        std::memcpy(cell(block, w), cell(old, w), (1 + from) * sizeof(std::uint64_t));
    blocks_[b] = std::move(block);
}

void CoverageCounts::add(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    std::size_t at = SIZE_MAX;  // the block being written (words come mostly in order)
    std::uint64_t* block = nullptr;
    for (const WordMask& m : words) {
        if (m.index / kBlockWords != at) {
            at = m.index / kBlockWords;
            block = writable(at);
        }
        std::uint32_t planes = std::uint32_t(block[0]);
        const std::size_t w = m.index % kBlockWords;
        std::uint64_t* c = block + 1 + w * (1 + planes);
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
            block = blocks_[at].get();
            planes = std::uint32_t(block[0]);
            block[1 + w * (1 + planes) + planes] = carry;
        }
    }
}

void CoverageCounts::remove(std::span<const WordMask> words, const ImageTarget& target, Delta& delta) {
    std::size_t at = SIZE_MAX;
    std::uint64_t* block = nullptr;
    for (const WordMask& m : words) {
        if (m.index / kBlockWords != at) {
            at = m.index / kBlockWords;
            block = writable(at);
        }
        const std::uint32_t planes = std::uint32_t(block[0]);
        std::uint64_t* c = block + 1 + (m.index % kBlockWords) * (1 + planes);
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
    const Block& p = blocks_[i / kBlockWords];
    return p ? cell(p, i % kBlockWords)[0] : 0;
}

std::uint32_t CoverageCounts::count(std::size_t i, int bit) const {
    const Block& p = blocks_[i / kBlockWords];
    if (!p) return 0;
    const std::uint64_t* c = cell(p, i % kBlockWords);
    std::uint32_t n = 0;
    for (std::uint32_t k = 0; k < planesOf(p); ++k) n |= std::uint32_t(c[1 + k] >> bit & 1) << k;
    return n;
}

std::size_t CoverageCounts::bytes() const {
    std::size_t n = blocks_.size() * sizeof(Block);
    forEachBlock([&](const void*, std::size_t bytes) { n += bytes; });
    return n;
}

}  // namespace shapevo
