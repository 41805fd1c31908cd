// GridSpec: the voxel grid that volume targets are baked into and primitives are voxelized over.
// Voxel (i, j, k) has its centre at origin + (i + 0.5, j + 0.5, k + 0.5) * voxelSize; rows run
// along x, wordsPerRow 64-bit words each. Every voxel test of every kind uses centre().
#pragma once
#include <cstddef>

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

}  // namespace shapevo
