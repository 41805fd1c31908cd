// CoverageLayout: which block of CoverageCounts, and which word in it, holds each 64-pixel word
// of a picture. Blocks are tiles a few words wide and many rows tall, not runs of whole rows:
// a tree's primitives are narrow and tall, so a child that changes one writes (and copies) fewer
// words of its parent's counts when the blocks are tiles.
//
// Promises:
//  - place(i) is a one-to-one map of the picture's words (row-major index i < words()) onto
//    (block < blocks(), offset < kBlockWords); words of a tile outside the picture stay unused.
//  - It costs a multiply and a few shifts (no division, no table).
#pragma once
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "score/image/coverage_block.hpp"

namespace shapevo {

class CoverageLayout {
public:
    static constexpr std::uint32_t kBlockWords = std::uint32_t(CoverageBlock::kPictureWords);
    /// The widest tile, in words (narrower pictures get tiles as wide as they are, rounded up).
    static constexpr std::uint32_t kTileWords = 2;
    static_assert(std::has_single_bit(kBlockWords) && std::has_single_bit(kTileWords) && kTileWords <= kBlockWords);

    struct Place {
        std::uint32_t block, offset;
    };

    CoverageLayout() = default;
    /// A picture of `rows` rows (at most 2^16) of `wordsPerRow` 64-pixel words (1 to 2^12).
    CoverageLayout(std::uint32_t wordsPerRow, std::uint32_t rows) : wordsPerRow_(wordsPerRow), rows_(rows) {
        if (wordsPerRow == 0 || wordsPerRow > (1u << 12) || rows > (1u << 16))
            throw std::logic_error("CoverageLayout: a picture wider than 2^18 or taller than 2^16 pixels");
        tileWordsLog2_ = std::uint32_t(std::countr_zero(std::min(kTileWords, std::bit_ceil(wordsPerRow))));
        tileRowsLog2_ = std::uint32_t(std::countr_zero(kBlockWords)) - tileWordsLog2_;
        tilesPerRow_ = (wordsPerRow + (1u << tileWordsLog2_) - 1) >> tileWordsLog2_;
        blocks_ = tilesPerRow_ * ((rows + (1u << tileRowsLog2_) - 1) >> tileRowsLog2_);
        // i / wordsPerRow as (i * magic) >> 40, exact while i * wordsPerRow < 2^40: i < words()
        // and the limits above make it at most 2^12 * 2^12 * 2^16.
        magic_ = ((std::uint64_t(1) << 40) + wordsPerRow - 1) / wordsPerRow;
    }

    std::size_t words() const { return std::size_t(wordsPerRow_) * rows_; }
    std::size_t blocks() const { return blocks_; }

    Place place(std::uint32_t i) const {
        const std::uint32_t row = std::uint32_t((std::uint64_t(i) * magic_) >> 40);
        const std::uint32_t col = i - row * wordsPerRow_;
        const std::uint32_t tileCols = (1u << tileWordsLog2_) - 1, tileRows = (1u << tileRowsLog2_) - 1;
        return {(row >> tileRowsLog2_) * tilesPerRow_ + (col >> tileWordsLog2_),
                ((row & tileRows) << tileWordsLog2_) | (col & tileCols)};
    }

private:
    std::uint32_t wordsPerRow_ = 0, rows_ = 0;
    std::uint32_t tileWordsLog2_ = 0, tileRowsLog2_ = 0, tilesPerRow_ = 0, blocks_ = 0;
    std::uint64_t magic_ = 0;
};

}  // namespace shapevo
