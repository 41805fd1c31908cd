// Voxelizer implementation: row intervals -> word masks; counting with popcount over touched rows.
#include "score/voxelizer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "score/box_rows.hpp"
#include "score/cone_rows.hpp"
#include "score/cylinder_rows.hpp"
#include "score/sphere_rows.hpp"

namespace shapevo {

Voxelizer::Voxelizer(const GridSpec& grid)
    : grid_(grid), words_(grid.wordsPerRow()), occupied_(grid.words(), 0), overlap_(grid.words(), 0),
      yMin_(std::size_t(grid.nz), INT32_MAX), yMax_(std::size_t(grid.nz), -1) {
    slices_.reserve(std::size_t(grid.nz));
}

void Voxelizer::markRows(long z, long y0, long y1, long lo, long hi) {
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

namespace {
/// True if every box axis is a distinct grid axis (the common case: unrotated grammars, mirrors).
bool axisAligned(const BoxFrame& b) {
    int seen = 0;
    for (int k = 0; k < 3; ++k) {
        int nonzero = 0, axis = 0;
        for (int j = 0; j < 3; ++j)
            if (b.a[k][j] != 0.0) ++nonzero, axis = j;
        if (nonzero != 1 || (seen & (1 << axis))) return false;
        seen |= 1 << axis;
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
    if (lo <= hi) markRows(z, y, y, lo, hi);
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
    switch (p.kind) {
    case PrimitiveKind::Box: addBox(p, counts); return;
    case PrimitiveKind::Cylinder: addRound(CylinderSolid::from(p), counts); return;
    case PrimitiveKind::Cone: addRound(ConeSolid::from(p), counts); return;
    case PrimitiveKind::Sphere: addRound(SphereSolid::from(p), counts); return;
    case PrimitiveKind::Mesh:
        if (meshes && p.mesh < meshes->size()) addMesh(p, (*meshes)[p.mesh], counts);
        return;
    }
}

template <class Solid>
void Voxelizer::addRound(const Solid& s, VoxelCounts& counts) {
    if (!s.valid()) return;
    const double reach[3] = {s.reach(0), s.reach(1), s.reach(2)};
    long first[3], last[3];
    if (!indexBounds(s.f.box.c, reach, first, last)) return;
    for (long z = first[2]; z <= last[2]; ++z) {
        const double cz = grid_.centre(2, z);
        for (long y = first[1]; y <= last[1]; ++y) {
            ++counts.rows;
            long lo, hi;
            if (chordInterval(s.chord(grid_.centre(1, y), cz), s.cx(), grid_, first[0], last[0], lo, hi))
                addRow(y, z, lo, hi, counts);
        }
    }
}

void Voxelizer::addMesh(const Primitive& p, const MeshShape& shape, VoxelCounts& counts) {
    if (!mesh_.place(p, shape)) return;
    double c[3], reach[3];
    for (int j = 0; j < 3; ++j) {
        c[j] = 0.5 * (mesh_.lo(j) + mesh_.hi(j));
        reach[j] = 0.5 * (mesh_.hi(j) - mesh_.lo(j));
    }
    long first[3], last[3];
    if (!indexBounds(c, reach, first, last)) return;
    counts.rows += std::uint64_t(last[1] - first[1] + 1) * std::uint64_t(last[2] - first[2] + 1);
    crossings_.clear();
    mesh_.collectCrossings(grid_, first[1], last[1], first[2], last[2], crossings_);
    // Bucket the crossings by row (a counting sort: the row keys are dense), then sort each
    // row's few crossings by x.
    const std::uint32_t ny = std::uint32_t(last[1] - first[1] + 1);
    const std::size_t rows = std::size_t(ny) * std::size_t(last[2] - first[2] + 1);
    rowEnd_.assign(rows + 1, 0);
    for (const RowCrossing& c : crossings_) ++rowEnd_[c.row + 1];
    for (std::size_t r = 0; r < rows; ++r) rowEnd_[r + 1] += rowEnd_[r];  // now: where row r starts
    byRow_.resize(crossings_.size());
    for (const RowCrossing& c : crossings_) byRow_[rowEnd_[c.row]++] = c;  // afterwards: where row r ends
    // Runs may start before a row's first crossing only if it crosses an odd number of
    // triangles (never for a closed mesh); the whole halo keeps even that case exact.
    const long xFirst = -long(grid_.nx), xLast = 2 * long(grid_.nx) - 1;
    for (std::uint32_t r = 0, begin = 0; r < rows; begin = rowEnd_[r], ++r) {
        const std::uint32_t end = rowEnd_[r];
        if (begin == end) continue;
        RowCrossing* c = byRow_.data() + begin;
        std::sort(c, c + (end - begin));
        const long y = first[1] + long(r % ny), z = first[2] + long(r / ny);
        rowRuns(c, end - begin, grid_, xFirst, xLast, [&](long lo, long hi) { addRow(y, z, lo, hi, counts); });
    }
}

void Voxelizer::addBox(const Primitive& p, VoxelCounts& counts) {
    const BoxFrame b = BoxFrame::from(p);
    if (!b.finite()) return;
    const long n[3] = {grid_.nx, grid_.ny, grid_.nz};
    const double reach[3] = {b.reach(0), b.reach(1), b.reach(2)};
    long first[3], last[3];
    if (!indexBounds(b.c, reach, first, last)) return;
    if (axisAligned(b)) {
        // Each slab depends on one grid axis only (the other products are exact zeros, and
        // v + 0 == v), so the covered voxels are a box of index ranges, one per axis.
        long range[3][2];
        for (int k = 0; k < 3; ++k) {
            int j = 0;
            while (b.a[k][j] == 0.0) ++j;
            if (!slabInterval(SlabLine::of(b, k, j, grid_), 0.0, grid_, first[j], last[j], range[j][0], range[j][1])) return;
        }
        // Everything below is arithmetic on the three ranges: rows off the grid in y or z count
        // their whole interval as outside, rows on it count the part beyond x.
        const long lo = range[0][0], hi = range[0][1];
        const std::uint64_t len = std::uint64_t(hi - lo + 1);
        const std::uint64_t rowsY = std::uint64_t(range[1][1] - range[1][0] + 1);
        const std::uint64_t rowsZ = std::uint64_t(range[2][1] - range[2][0] + 1);
        counts.rows += rowsY * rowsZ;
        const long gy0 = std::max(range[1][0], 0L), gy1 = std::min(range[1][1], n[1] - 1);
        const long gz0 = std::max(range[2][0], 0L), gz1 = std::min(range[2][1], n[2] - 1);
        const long gx0 = std::max(lo, 0L), gx1 = std::min(hi, n[0] - 1);
        const std::uint64_t inGridRows =
            (gy0 <= gy1 && gz0 <= gz1) ? std::uint64_t(gy1 - gy0 + 1) * std::uint64_t(gz1 - gz0 + 1) : 0;
        const std::uint64_t inGridLen = gx0 <= gx1 ? std::uint64_t(gx1 - gx0 + 1) : 0;
        counts.outside += (rowsY * rowsZ - inGridRows) * len + inGridRows * (len - inGridLen);
        if (inGridRows == 0 || inGridLen == 0) return;
        for (long z = gz0; z <= gz1; ++z) markRows(z, gy0, gy1, gx0, gx1);
        return;
    }
    const SlabLine slab[3] = {SlabLine::of(b, 0, 0, grid_), SlabLine::of(b, 1, 0, grid_), SlabLine::of(b, 2, 0, grid_)};
    auto rowInterval = [&](double cy, double cz, long& lo, long& hi) {
        lo = first[0];
        hi = last[0];
        for (int k = 0; k < 3; ++k) {
            long l, h;
            if (!slabInterval(slab[k], b.rowTerm(k, cy, cz), grid_, lo, hi, l, h)) return false;
            lo = l;
            hi = h;
        }
        return true;
    };
    for (long z = first[2]; z <= last[2]; ++z) {
        const double cz = grid_.centre(2, z);
        for (long y = first[1]; y <= last[1]; ++y) {
            ++counts.rows;
            long lo, hi;
            if (rowInterval(grid_.centre(1, y), cz, lo, hi)) addRow(y, z, lo, hi, counts);
        }
    }
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
