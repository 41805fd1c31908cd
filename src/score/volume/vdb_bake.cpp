// Baking level sets into the scorer's dense bit rows: grid choice, parallel inside test, hash.
#include "score/volume/vdb_bake.hpp"

#include "base/hash.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shapevo::vdbbake {

openvdb::BBoxd activeWorldBounds(const openvdb::FloatGrid& grid) {
    const openvdb::CoordBBox ib = grid.evalActiveVoxelBoundingBox();
    // Index coordinates are voxel centres; the voxels themselves reach half a voxel further.
    const openvdb::BBoxd cells(ib.min().asVec3d() - 0.5, ib.max().asVec3d() + 0.5);
    return grid.transform().indexToWorld(cells);
}

GridSpec paddedGrid(const openvdb::BBoxd& bounds, double voxelSize, const openvdb::Vec3d& anchor) {
    const openvdb::Vec3d extent = bounds.extents();
    const double pad = 0.25 * std::max({extent[0], extent[1], extent[2]});
    GridSpec spec;
    spec.voxelSize = voxelSize;
    int* n[3] = {&spec.nx, &spec.ny, &spec.nz};
    for (int a = 0; a < 3; ++a) {
        const double lo = bounds.min()[a] - pad, hi = bounds.max()[a] + pad;
        spec.origin[a] = anchor[a] + std::floor((lo - anchor[a]) / voxelSize) * voxelSize;
        const double cells = std::ceil((hi - spec.origin[a]) / voxelSize);
        *n[a] = int(std::clamp(cells, 1.0, 2147483647.0));
    }
    return spec;
}

namespace {
/// First and one-past-last dense index along `axis` whose centre lies within [lo, hi].
std::pair<long, long> centreRange(const GridSpec& spec, int axis, int n, double lo, double hi) {
    const double o = spec.origin[axis], h = spec.voxelSize;
    const double first = std::ceil((lo - o) / h - 0.5), last = std::floor((hi - o) / h - 0.5);
    const long begin = long(std::clamp(first, 0.0, double(n)));
    const long end = long(std::clamp(last + 1.0, 0.0, double(n)));
    return {begin, std::max(begin, end)};
}
}  // namespace

void bakeInside(const openvdb::FloatGrid& grid, const GridSpec& spec, std::vector<std::uint64_t>& bits) {
    // Widen the active bounds by one target voxel so rounding never drops a boundary voxel.
    openvdb::BBoxd box = activeWorldBounds(grid);
    const double margin = grid.transform().voxelSize().length();
    box.expand(margin);
    // plain variables, not structured bindings: lambdas may capture them in C++20 with every compiler
    const auto xr = centreRange(spec, 0, spec.nx, box.min()[0], box.max()[0]);
    const auto yr = centreRange(spec, 1, spec.ny, box.min()[1], box.max()[1]);
    const auto zr = centreRange(spec, 2, spec.nz, box.min()[2], box.max()[2]);
    const long x0 = xr.first, x1 = xr.second, y0 = yr.first, y1 = yr.second, z0 = zr.first, z1 = zr.second;
    if (x0 >= x1 || y0 >= y1 || z0 >= z1) return;
    const std::size_t wordsPerRow = std::size_t(spec.wordsPerRow());

    // One z slice per task: rows of different slices never share a word, so no locking.
    tbb::parallel_for(tbb::blocked_range<long>(z0, z1), [&](const tbb::blocked_range<long>& zs) {
        openvdb::FloatGrid::ConstAccessor accessor = grid.getConstAccessor();  // per thread: caches
        const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, grid.transform());
        for (long z = zs.begin(); z != zs.end(); ++z) {
            const double cz = spec.centre(2, z);
            for (long y = y0; y < y1; ++y) {
                const double cy = spec.centre(1, y);
                std::uint64_t* row = bits.data() + (std::size_t(z) * std::size_t(spec.ny) + std::size_t(y)) * wordsPerRow;
                for (long x = x0; x < x1; ++x) {
                    if (sampler.wsSample(openvdb::Vec3d(spec.centre(0, x), cy, cz)) <= 0.0f)
                        row[x >> 6] |= std::uint64_t(1) << (x & 63);
                }
            }
        }
    });
}

std::uint64_t popcount(const std::vector<std::uint64_t>& bits) {
    std::uint64_t n = 0;
    for (std::uint64_t w : bits) n += std::uint64_t(std::popcount(w));
    return n;
}

std::uint64_t targetHash(const VolumeTarget& target) {
    Hasher h;
    const GridSpec& g = target.grid;
    h.addNumber(double(g.origin.x)), h.addNumber(double(g.origin.y)), h.addNumber(double(g.origin.z));
    h.addNumber(double(g.voxelSize));
    h.addNumber(std::int32_t(g.nx)), h.addNumber(std::int32_t(g.ny)), h.addNumber(std::int32_t(g.nz));
    for (std::uint64_t w : target.fill) h.addNumber(w);
    for (std::uint64_t w : target.avoid) h.addNumber(w);
    return h.digest();
}

}  // namespace shapevo::vdbbake
