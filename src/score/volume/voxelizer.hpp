// Voxelizer: turns a model's primitives into bit rows over the target grid and counts them
// against the target. For each voxel row a primitive crosses, the covered x-interval is computed
// directly and OR-ed in as word masks; a voxel covered twice sets its overlap bit. Each kind's
// inside test and row intervals live in its kind file (shape/kinds/*.hpp, K::voxelize), called
// with static dispatch per primitive; this class is their row interface (grid, indexBounds,
// addRow, markRows, scratch).
// Voxel centres outside the grid (within a halo of one grid extent on every side) count as
// "outside", once per primitive that covers them.
//
// addRecorded/replay serve incremental scoring (score/primitive_cache.hpp).
// Bookkeeping is per z slice: the range of rows [yMin, yMax] written since the last count, so
// counting and clearing sweep contiguous memory and touch nothing else.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "score/volume/volume_target.hpp"
#include "shape/kinds.hpp"
#include "shape/primitive.hpp"

namespace shapevo {

struct VoxelCounts {
    std::uint64_t occupied = 0;  ///< grid voxels covered by the model
    std::uint64_t inside = 0;    ///< covered and in the fill target
    std::uint64_t avoided = 0;   ///< covered and in an avoid target
    std::uint64_t overlap = 0;   ///< grid voxels covered by two or more primitives
    std::uint64_t outside = 0;   ///< covered voxel centres outside the grid (per primitive)
    std::uint64_t rows = 0;      ///< voxel rows a primitive was rasterized into (work measure for benchmarks)
    bool operator==(const VoxelCounts&) const = default;
};

/// One markRows call a primitive made: x-interval [lo, hi] of rows y0..y1 of slice z (what
/// PrimitiveCache keeps for it).
struct VoxelRun {
    std::int32_t z, y0, y1, lo, hi;
};

class Voxelizer {
public:
    explicit Voxelizer(const GridSpec& grid);
    /// Voxelize all primitives of `geometry` and count them against `target` (same grid);
    /// leaves the voxelizer empty for the next model.
    VoxelCounts score(const Geometry& geometry, const VolumeTarget& target);
    /// Voxelize one primitive without counting; `occupancy()` holds the bit rows until clear().
    /// A Mesh primitive finds its mesh in `meshes` (it covers nothing if that is missing).
    void add(const Primitive& p, const std::vector<MeshShape>* meshes, VoxelCounts& counts);
    /// add(), appending every run of rows it writes to `runs` (replay() writes them again).
    void addRecorded(const Primitive& p, const std::vector<MeshShape>* meshes, VoxelCounts& counts, std::vector<VoxelRun>& runs);
    /// True for a primitive whose rows cost no more to compute than to replay from a cache (an
    /// axis-aligned box: one box of index ranges, one markRows per slice either way), so
    /// incremental scoring draws it directly instead of hashing and looking it up.
    static bool drawsAsFastAsReplay(const Primitive& p);
    /// Write runs that addRecorded() gave: the same voxels (and overlaps) as adding the primitive.
    void replay(std::span<const VoxelRun> runs);
    /// Count what was added against `target` (same grid) and clear; `counts` brings what add()
    /// counted (outside, rows).
    VoxelCounts countAgainst(const VolumeTarget& target, VoxelCounts counts);
    const std::vector<std::uint64_t>& occupancy() const { return occupied_; }
    void clear();
    const GridSpec& grid() const { return grid_; }

    // ---- The row interface of the kinds' voxel code (K::voxelize) -----------------------------
    /// Index ranges [first, last] per axis of the voxels within `reach` of `c` (plus one voxel of
    /// padding), clamped to the halo; false if that is empty (or NaN).
    bool indexBounds(const double c[3], const double reach[3], long first[3], long last[3]) const;
    /// Cover [lo, hi] of row (y, z), counting what falls outside the grid. (addRows for one row,
    /// written out: the round kinds call it for every row, and the products cost 2 % there.)
    void addRow(long y, long z, long lo, long hi, VoxelCounts& counts) {
        if (z < 0 || z >= grid_.nz || y < 0 || y >= grid_.ny) {
            counts.outside += std::uint64_t(hi - lo + 1);
            return;
        }
        if (lo < 0) {
            counts.outside += std::uint64_t(std::min(hi, -1L) - lo + 1);
            lo = 0;
        }
        if (hi >= grid_.nx) {
            counts.outside += std::uint64_t(hi - std::max(lo, long(grid_.nx)) + 1);
            hi = grid_.nx - 1;
        }
        if (lo <= hi) markRows(z, y, y, lo, hi);
    }
    /// Cover [lo, hi] of rows y0..y1 of slice z (as addRow on each, in one run).
    void addRows(long y0, long y1, long z, long lo, long hi, VoxelCounts& counts);
    /// OR the same x-interval [lo, hi] (inside the grid) into rows y0..y1 of slice z.
    void markRows(long z, long y0, long y1, long lo, long hi);
    /// Kind K's reusable work space (K::VoxelScratch).
    template <class K>
    auto& scratch() { return voxelScratch<K>(scratch_); }

private:

    GridSpec grid_;
    int words_;
    std::vector<std::uint64_t> occupied_, overlap_;
    std::vector<std::int32_t> yMin_, yMax_;  ///< per z slice: written rows, yMin > yMax if none
    std::vector<std::uint32_t> slices_;      ///< z slices with rows written, in first-touch order
    KindVoxelScratch scratch_;               ///< the kinds' work spaces (the mesh kind's buffers)
    std::vector<VoxelRun>* recording_ = nullptr;  ///< during addRecorded: where markRows appends its runs
};

}  // namespace shapevo
