// Voxelizer implementation: row intervals -> word masks; counting with popcount over touched rows.
#include "score/voxelizer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "score/box_rows.hpp"

namespace shapevo {

Voxelizer::Voxelizer(const GridSpec& grid)
    : grid_(grid), words_(grid.wordsPerRow()), occupied_(grid.words(), 0), overlap_(grid.words(), 0),
      rowTouched_(grid.rows(), 0) {
    touched_.reserve(grid.rows());
}

void Voxelizer::markRow(std::size_t row, long lo, long hi) {
    std::uint64_t* occ = &occupied_[row * std::size_t(words_)];
    std::uint64_t* ovl = &overlap_[row * std::size_t(words_)];
    if (!rowTouched_[row]) {
        rowTouched_[row] = 1;
        touched_.push_back(std::uint32_t(row));
    }
    const long w0 = lo >> 6, w1 = hi >> 6;
    for (long w = w0; w <= w1; ++w) {
        std::uint64_t mask = ~0ULL;
        if (w == w0) mask &= ~0ULL << (lo & 63);
        if (w == w1) mask &= ~0ULL >> (63 - (hi & 63));
        ovl[w] |= occ[w] & mask;
        occ[w] |= mask;
    }
}

void Voxelizer::add(const Primitive& p, VoxelCounts& counts) {
    const BoxFrame b = BoxFrame::from(p);
    if (!b.finite()) return;
    const long n[3] = {grid_.nx, grid_.ny, grid_.nz};
    long first[3], last[3];
    for (int j = 0; j < 3; ++j) {
        const double reach = b.reach(j);
        const double t0 = (b.c[j] - reach - grid_.origin[j]) / grid_.voxelSize - 0.5;
        const double t1 = (b.c[j] + reach - grid_.origin[j]) / grid_.voxelSize - 0.5;
        // one voxel of padding: the exact per-row test decides, the bounds only limit the work
        first[j] = long(std::max(std::floor(t0) - 1.0, double(-n[j])));
        last[j] = long(std::min(std::ceil(t1) + 1.0, double(2 * n[j] - 1)));
        if (first[j] > last[j]) return;
    }
    for (long z = first[2]; z <= last[2]; ++z) {
        const double cz = grid_.centre(2, z);
        const bool zInside = z >= 0 && z < n[2];
        for (long y = first[1]; y <= last[1]; ++y) {
            const double cy = grid_.centre(1, y);
            long lo = first[0], hi = last[0];
            bool any = true;
            for (int k = 0; k < 3 && any; ++k) {
                long l, h;
                any = slabInterval(b, k, b.rowTerm(k, cy, cz), grid_, lo, hi, l, h);
                lo = l;
                hi = h;
            }
            ++counts.rows;
            if (!any) continue;
            if (!zInside || y < 0 || y >= n[1]) {
                counts.outside += std::uint64_t(hi - lo + 1);
                continue;
            }
            if (lo < 0) {
                counts.outside += std::uint64_t(std::min(hi, -1L) - lo + 1);
                lo = 0;
            }
            if (hi >= n[0]) {
                counts.outside += std::uint64_t(hi - std::max(lo, n[0]) + 1);
                hi = n[0] - 1;
            }
            if (lo <= hi) markRow(std::size_t(z) * std::size_t(n[1]) + std::size_t(y), lo, hi);
        }
    }
}

VoxelCounts Voxelizer::score(const std::vector<Primitive>& primitives, const VolumeTarget& target) {
    VoxelCounts counts;
    for (const Primitive& p : primitives) add(p, counts);
    const bool hasAvoid = target.avoidCount > 0;
    for (std::uint32_t row : touched_) {
        const std::size_t base = std::size_t(row) * std::size_t(words_);
        for (int w = 0; w < words_; ++w) {
            const std::uint64_t o = occupied_[base + w];
            counts.occupied += std::uint64_t(std::popcount(o));
            counts.inside += std::uint64_t(std::popcount(o & target.fill[base + w]));
            if (hasAvoid) counts.avoided += std::uint64_t(std::popcount(o & target.avoid[base + w]));
            counts.overlap += std::uint64_t(std::popcount(overlap_[base + w]));
        }
    }
    clear();
    return counts;
}

void Voxelizer::clear() {
    for (std::uint32_t row : touched_) {
        const std::size_t base = std::size_t(row) * std::size_t(words_);
        std::fill_n(&occupied_[base], words_, 0);
        std::fill_n(&overlap_[base], words_, 0);
        rowTouched_[row] = 0;
    }
    touched_.clear();
}

}  // namespace shapevo
