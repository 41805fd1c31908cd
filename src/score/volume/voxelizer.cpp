// Voxelizer implementation: row intervals -> word masks; counting with popcount over touched rows.
#include "score/volume/voxelizer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>


namespace shapevo {

Voxelizer::Voxelizer(const GridSpec& grid)
    : grid_(grid), words_(grid.wordsPerRow()), occupied_(grid.words(), 0), overlap_(grid.words(), 0),
      yMin_(std::size_t(grid.nz), INT32_MAX), yMax_(std::size_t(grid.nz), -1) {
    slices_.reserve(std::size_t(grid.nz));
}

void Voxelizer::markRows(long z, long y0, long y1, long lo, long hi) {
    if (recording_) [[unlikely]]
        recording_->push_back({std::int32_t(z), std::int32_t(y0), std::int32_t(y1), std::int32_t(lo), std::int32_t(hi)});
    if (yMin_[z] > yMax_[z]) slices_.push_back(std::uint32_t(z));
    yMin_[z] = std::min<std::int32_t>(yMin_[z], std::int32_t(y0));
    yMax_[z] = std::max<std::int32_t>(yMax_[z], std::int32_t(y1));
    const long w0 = lo >> 6, w1 = hi >> 6;
    const std::uint64_t first = ~0ULL << (lo & 63), last = ~0ULL >> (63 - (hi & 63));
    const std::size_t W = std::size_t(words_);
    std::uint64_t* occ = &occupied_[(std::size_t(z) * std::size_t(grid_.ny) + std::size_t(y0)) * W];
    std::uint64_t* ovl = &overlap_[(std::size_t(z) * std::size_t(grid_.ny) + std::size_t(y0)) * W];
    if (w0 == w1) {  // the common case: the interval lies in one word
        const std::uint64_t m = first & last;
        for (long y = y0; y <= y1; ++y, occ += W, ovl += W) {
            ovl[w0] |= occ[w0] & m;
            occ[w0] |= m;
        }
        return;
    }
    for (long y = y0; y <= y1; ++y, occ += W, ovl += W) {
        ovl[w0] |= occ[w0] & first;
        occ[w0] |= first;
        for (long w = w0 + 1; w < w1; ++w) {
            ovl[w] |= occ[w];
            occ[w] = ~0ULL;
        }
        ovl[w1] |= occ[w1] & last;
        occ[w1] |= last;
    }
}

void Voxelizer::addRows(long y0, long y1, long z, long lo, long hi, VoxelCounts& counts) {
    const long nx = grid_.nx;
    const std::uint64_t length = std::uint64_t(hi - lo + 1), rows = std::uint64_t(y1 - y0 + 1);
    if (z < 0 || z >= grid_.nz) {
        counts.outside += rows * length;
        return;
    }
    const long gy0 = std::max(y0, 0L), gy1 = std::min(y1, long(grid_.ny) - 1);
    const std::uint64_t inGrid = gy0 <= gy1 ? std::uint64_t(gy1 - gy0 + 1) : 0;
    counts.outside += (rows - inGrid) * length;
    if (inGrid == 0) return;
    if (lo < 0) {
        counts.outside += inGrid * std::uint64_t(std::min(hi, -1L) - lo + 1);
        lo = 0;
    }
    if (hi >= nx) {
        counts.outside += inGrid * std::uint64_t(hi - std::max(lo, nx) + 1);
        hi = nx - 1;
    }
    if (lo <= hi) markRows(z, gy0, gy1, lo, hi);
}

bool Voxelizer::indexBounds(const double c[3], const double reach[3], long first[3], long last[3]) const {
    const long n[3] = {grid_.nx, grid_.ny, grid_.nz};
    for (int j = 0; j < 3; ++j) {
        const double t0 = (c[j] - reach[j] - grid_.origin[j]) / grid_.voxelSize - 0.5;
        const double t1 = (c[j] + reach[j] - grid_.origin[j]) / grid_.voxelSize - 0.5;
        // one voxel of padding: the exact per-row test decides, the bounds only limit the work;
        // clamped as doubles first, so a primitive far away cannot overflow the conversion
        const double lo = std::max(std::floor(t0) - 1.0, double(-n[j])), hi = std::min(std::ceil(t1) + 1.0, double(2 * n[j] - 1));
        if (!(lo <= hi)) return false;  // outside the halo (or NaN)
        first[j] = long(lo);
        last[j] = long(hi);
    }
    return true;
}

void Voxelizer::add(const Primitive& p, const std::vector<MeshShape>* meshes, VoxelCounts& counts) {
    visitKind(p.kind, [&](auto kind) { decltype(kind)::type::voxelize(p, meshes, *this, counts); });
}

void Voxelizer::addRecorded(const Primitive& p, const std::vector<MeshShape>* meshes, VoxelCounts& counts,
                            std::vector<VoxelRun>& runs) {
    recording_ = &runs;
    add(p, meshes, counts);
    recording_ = nullptr;
}

bool Voxelizer::drawsAsFastAsReplay(const Primitive& p) {
    return p.kind == PrimitiveKind::Box && axisAligned(BoxFrame::from(p));
}

void Voxelizer::replay(std::span<const VoxelRun> runs) {
    for (const VoxelRun& r : runs) markRows(r.z, r.y0, r.y1, r.lo, r.hi);
}

namespace {
/// Count one block of words against the target and zero it; the avoid term only if asked.
template <bool kAvoid>
void countAndClear(std::uint64_t* occ, std::uint64_t* ovl, const std::uint64_t* fill, const std::uint64_t* avoid,
                   std::size_t begin, std::size_t end, VoxelCounts& c) {
    std::uint64_t occupied = 0, inside = 0, avoided = 0, overlap = 0;
    for (std::size_t i = begin; i < end; ++i) {
        const std::uint64_t o = occ[i];
        occupied += std::uint64_t(std::popcount(o));
        inside += std::uint64_t(std::popcount(o & fill[i]));
        if constexpr (kAvoid) avoided += std::uint64_t(std::popcount(o & avoid[i]));
        overlap += std::uint64_t(std::popcount(ovl[i]));
        occ[i] = 0;
        ovl[i] = 0;
    }
    c.occupied += occupied;
    c.inside += inside;
    c.avoided += avoided;
    c.overlap += overlap;
}
}  // namespace

VoxelCounts Voxelizer::score(const Geometry& geometry, const VolumeTarget& target) {
    VoxelCounts counts;
    for (const Primitive& p : geometry.primitives) add(p, geometry.meshes, counts);
    return countAgainst(target, counts);
}

VoxelCounts Voxelizer::countAgainst(const VolumeTarget& target, VoxelCounts counts) {
    const std::size_t W = std::size_t(words_), ny = std::size_t(grid_.ny);
    // Count and clear in one sweep over each slice's written rows (contiguous words).
    for (std::uint32_t z : slices_) {
        const std::size_t begin = (std::size_t(z) * ny + std::size_t(yMin_[z])) * W;
        const std::size_t end = (std::size_t(z) * ny + std::size_t(yMax_[z]) + 1) * W;
        if (target.avoidCount > 0)
            countAndClear<true>(occupied_.data(), overlap_.data(), target.fill.data(), target.avoid.data(), begin, end, counts);
        else
            countAndClear<false>(occupied_.data(), overlap_.data(), target.fill.data(), nullptr, begin, end, counts);
        yMin_[z] = INT32_MAX;
        yMax_[z] = -1;
    }
    slices_.clear();
    return counts;
}

void Voxelizer::clear() {
    const std::size_t W = std::size_t(words_), ny = std::size_t(grid_.ny);
    for (std::uint32_t z : slices_) {
        const std::size_t begin = (std::size_t(z) * ny + std::size_t(yMin_[z])) * W;
        const std::size_t end = (std::size_t(z) * ny + std::size_t(yMax_[z]) + 1) * W;
        std::fill(occupied_.begin() + std::ptrdiff_t(begin), occupied_.begin() + std::ptrdiff_t(end), 0);
        std::fill(overlap_.begin() + std::ptrdiff_t(begin), overlap_.begin() + std::ptrdiff_t(end), 0);
        yMin_[z] = INT32_MAX;
        yMax_[z] = -1;
    }
    slices_.clear();
}

}  // namespace shapevo
