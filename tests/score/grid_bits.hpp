// Test helper: one voxel of a dense bit grid (GridSpec's layout: rows of 64-bit words along x,
// row (k * ny + j)), for brute-force comparisons of baked targets.
#pragma once
#include <cstdint>
#include <vector>

#include "shape/grid_spec.hpp"

namespace shapevo::test {

inline bool gridBit(const std::vector<std::uint64_t>& bits, const GridSpec& g, int i, int j, int k) {
    const std::size_t row = (std::size_t(k) * std::size_t(g.ny) + std::size_t(j)) * std::size_t(g.wordsPerRow());
    return (bits[row + std::size_t(i >> 6)] >> (i & 63)) & 1u;
}

}  // namespace shapevo::test
