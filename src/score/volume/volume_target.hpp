// VolumeTarget: a target volume baked into a dense grid of bit rows, ready for the scorer.
// Rows run along x: row (y, z) starts at word (z * ny + y) * wordsPerRow, bit i of the row is voxel x = i.
// The grid itself (GridSpec) lives in shape/grid_spec.hpp, where the kinds' row code sees it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "shape/grid_spec.hpp"

namespace shapevo {

struct VolumeTarget {
    GridSpec grid;
    std::vector<std::uint64_t> fill;   ///< voxels the model should fill (bit rows)
    std::vector<std::uint64_t> avoid;  ///< voxels the model must avoid (bit rows, may be all zero)
    std::uint64_t fillCount = 0;
    std::uint64_t avoidCount = 0;
    std::uint64_t hash = 0;            ///< XXH3-64 of grid spec and bits; identifies the target in outputs
    /// hash64 of each target file's bytes as they were read (what hashFile gives), in the order
    /// of the specs: a run records its inputs without reading the files again.
    std::vector<std::uint64_t> fileHashes;
};

}  // namespace shapevo
