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

namespace {
/// True if every box axis is a grid axis (the common case: unrotated grammars, mirrors).
bool axisAligned(const BoxFrame& b) {
    for (int k = 0; k < 3; ++k) {
        int nonzero = 0;
        for (int j = 0; j < 3; ++j) nonzero += b.a[k][j] != 0.0;
        if (nonzero != 1) return false;
    }
    return true;
}
}  // namespace

void Voxelizer::addRow(long y, long z, long lo, long hi, VoxelCounts& counts) {
    const long nx = grid_.nx;
    if (z < 0 || z >= grid_.nz || y < 0 || y >= grid_.ny) {
        counts.outside += std::uint64_t(hi - lo + 1);
        return;
    }
    if (lo < 0) {
        counts.outside += std::uint64_t(std::min(hi, -1L) - lo + 1);
        lo = 0;
    }
    if (hi >= nx) {
        counts.outside += std::uint64_t(hi - std::max(lo, nx) + 1);
        hi = nx - 1;
    }
    if (lo <= hi) markRow(std::size_t(z) * std::size_t(grid_.ny) + std::size_t(y), lo, hi);
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
    const SlabAlongX slab[3] = {SlabAlongX::of(b, 0, grid_), SlabAlongX::of(b, 1, grid_), SlabAlongX::of(b, 2, grid_)};
    auto rowInterval = [&](double cy, double cz, long& lo, long& hi) {
        lo = first[0];
        hi = last[0];
        for (int k = 0; k < 3; ++k) {
            long l, h;
            if (!slabInterval(b, k, slab[k], b.rowTerm(k, cy, cz), grid_, lo, hi, l, h)) return false;
            lo = l;
            hi = h;
        }
        return true;
    };
    if (axisAligned(b)) {
        // Each slab depends on one grid axis only (the other products are exact zeros), so the
        // x-interval is the same on every row, and a row passes or fails by its y and z alone.
        int governs[3];  // governs[j] = the slab whose normal is grid axis j
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j)
                if (b.a[k][j] != 0.0) governs[j] = k;
        const double y0 = grid_.centre(1, first[1]), z0 = grid_.centre(2, first[2]);
        long lo, hi;
        const int kx = governs[0];
        if (!slabInterval(b, kx, slab[kx], b.rowTerm(kx, y0, z0), grid_, first[0], last[0], lo, hi)) return;
        long range[3][2];  // passing index range along y (1) and z (2)
        for (int j = 1; j < 3; ++j) {
            const int k = governs[j];
            range[j][0] = last[j] + 1;
            range[j][1] = last[j];
            for (long i = first[j]; i <= last[j]; ++i) {
                const double cy = j == 1 ? grid_.centre(1, i) : y0, cz = j == 2 ? grid_.centre(2, i) : z0;
                if (!b.inSlab(k, grid_.centre(0, lo), b.rowTerm(k, cy, cz))) continue;
                range[j][0] = std::min(range[j][0], i);
                range[j][1] = i;
            }
        }
        for (long z = range[2][0]; z <= range[2][1]; ++z)
            for (long y = range[1][0]; y <= range[1][1]; ++y) {
                ++counts.rows;
                addRow(y, z, lo, hi, counts);
            }
        return;
    }
    for (long z = first[2]; z <= last[2]; ++z) {
        const double cz = grid_.centre(2, z);
        for (long y = first[1]; y <= last[1]; ++y) {
            ++counts.rows;
            long lo, hi;
            if (rowInterval(grid_.centre(1, y), cz, lo, hi)) addRow(y, z, lo, hi, counts);
        }
    }
}

VoxelCounts Voxelizer::score(const std::vector<Primitive>& primitives, const VolumeTarget& target) {
    VoxelCounts counts;
    for (const Primitive& p : primitives) add(p, counts);
    const bool hasAvoid = target.avoidCount > 0;
    // Count and clear in one pass over the touched rows only.
    for (std::uint32_t row : touched_) {
        const std::size_t base = std::size_t(row) * std::size_t(words_);
        for (int w = 0; w < words_; ++w) {
            const std::uint64_t o = occupied_[base + w];
            counts.occupied += std::uint64_t(std::popcount(o));
            counts.inside += std::uint64_t(std::popcount(o & target.fill[base + w]));
            if (hasAvoid) counts.avoided += std::uint64_t(std::popcount(o & target.avoid[base + w]));
            counts.overlap += std::uint64_t(std::popcount(overlap_[base + w]));
            occupied_[base + w] = 0;
            overlap_[base + w] = 0;
        }
        rowTouched_[row] = 0;
    }
    touched_.clear();
    return counts;
}

void Voxelizer::clear() {
    for (std::uint32_t row : touched_) {
        const std::size_t base = std::size_t(row) * std::size_t(words_);
        for (int w = 0; w < words_; ++w) occupied_[base + w] = overlap_[base + w] = 0;
        rowTouched_[row] = 0;
    }
    touched_.clear();
}

}  // namespace shapevo
