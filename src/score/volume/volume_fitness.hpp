// Volume fitness: the two scores of the papers over voxel counts (settings: score/fitness_settings.hpp).
//  - smootherstep (ga-shape-grammars.txt eq. 2-6):
//      f = alpha*step(in, 0, T) - beta*step(out + overlap, 0, 2T) - gamma*step(genes, l_opt, l_max)
//    where out = covered voxels not in the fill target (+ outside the grid), T = fill voxels.
//  - weighted sum s_vol (shapegenetics.txt §8): fill*in + empty*(covered, not fill, not avoid)
//      + avoid*avoided + outside*outside + overlap*overlap  (negative weights punish).
#pragma once
#include <cstdint>

#include "score/fitness_settings.hpp"
#include "score/volume/voxelizer.hpp"

namespace shapevo {

double volumeFitness(const FitnessSettings& s, const VoxelCounts& c, std::uint64_t targetVoxels, std::uint32_t genes);

/// Intersection over union of the model's voxels (outside ones included) and the fill target.
inline double voxelIoU(const VoxelCounts& c, std::uint64_t targetVoxels) {
    const double uni = double(c.occupied + c.outside + targetVoxels - c.inside);
    return uni > 0 ? double(c.inside) / uni : 0.0;
}

}  // namespace shapevo
