// Internal to loadVolumeTarget: choosing the dense grid for a set of level sets, baking each
// level set's inside into bit rows, and the XXH3-64 hash that identifies the baked target.
#pragma once
#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>

#include "score/volume/volume_target.hpp"

namespace shapevo::vdbbake {

/// World-space bounds of a grid's active voxels (whole voxels, not centres).
openvdb::BBoxd activeWorldBounds(const openvdb::FloatGrid& grid);

/// Largest dense grid we agree to allocate, in voxels (two bit arrays of 512 MiB each).
constexpr std::uint64_t kMaxDenseVoxels = std::uint64_t(1) << 32;

/// Dense grid covering `bounds` padded by 25% of its largest extent on every side, with voxel
/// size `voxelSize` and voxel corners on the lattice `anchor + k * voxelSize`.
GridSpec paddedGrid(const openvdb::BBoxd& bounds, double voxelSize, const openvdb::Vec3d& anchor);

/// Sets the bit of every dense voxel whose centre samples the level set at <= 0 (trilinear
/// BoxSampler, inactive values included). Voxels outside the grid's active bounds are skipped:
/// for a level set they lie outside the surface. Returns nothing; bits are OR-ed into `bits`.
void bakeInside(const openvdb::FloatGrid& grid, const GridSpec& spec, std::vector<std::uint64_t>& bits);

std::uint64_t popcount(const std::vector<std::uint64_t>& bits);

/// XXH3-64 over origin.xyz and voxelSize (IEEE-754 bits), nx, ny, nz (32-bit), then the fill
/// and avoid words, every value fed as little-endian bytes so the hash is the same on any host.
std::uint64_t targetHash(const VolumeTarget& target);

}  // namespace shapevo::vdbbake
