// VolumeTarget: a target volume baked into a dense grid of bit rows, ready for the scorer.
// Rows run along x: row (y, z) starts at word (z * ny + y) * wordsPerRow, bit i of the row is voxel x = i.
// Voxel (i, j, k) has its centre at origin + (i + 0.5, j + 0.5, k + 0.5) * voxelSize.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace shapevo {

struct GridSpec {
    glm::dvec3 origin{0.0};  ///< corner of voxel (0,0,0)
    double voxelSize = 1.0;
    int nx = 0, ny = 0, nz = 0;

    int wordsPerRow() const { return (nx + 63) / 64; }
    std::size_t rows() const { return std::size_t(ny) * std::size_t(nz); }
    std::size_t words() const { return rows() * std::size_t(wordsPerRow()); }
    /// Centre of voxel index i along an axis; the one formula every voxel test uses.
    double centre(int axis, long i) const { return origin[axis] + (double(i) + 0.5) * voxelSize; }
};

struct VolumeTarget {
    GridSpec grid;
    std::vector<std::uint64_t> fill;   ///< voxels the model should fill (bit rows)
    std::vector<std::uint64_t> avoid;  ///< voxels the model must avoid (bit rows, may be all zero)
    std::uint64_t fillCount = 0;
    std::uint64_t avoidCount = 0;
    std::uint64_t hash = 0;            ///< XXH3-64 of grid spec and bits; identifies the target in outputs
};

}  // namespace shapevo
