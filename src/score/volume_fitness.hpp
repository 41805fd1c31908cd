// Volume fitness: the two scores of the papers over voxel counts.
//  - smootherstep (ga-shape-grammars.txt eq. 2-6):
//      f = alpha*step(in, 0, T) - beta*step(out + overlap, 0, 2T) - gamma*step(genes, l_opt, l_max)
//    where out = covered voxels not in the fill target (+ outside the grid), T = fill voxels.
//  - weighted sum s_vol (shapegenetics.txt §8): fill*in + empty*(covered, not fill, not avoid)
//      + avoid*avoided + outside*outside + overlap*overlap  (negative weights punish).
#pragma once
#include <cstdint>

#include "score/voxelizer.hpp"

namespace shapevo {

/// step(x, lo, hi): 0 below lo, 1 above hi, Perlin's smootherstep 6t^5 - 15t^4 + 10t^3 between.
inline double smootherstep(double x, double lo, double hi) {
    if (x <= lo) return 0.0;
    if (x >= hi) return 1.0;
    const double t = (x - lo) / (hi - lo);
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

struct VolumeFitnessSettings {
    enum class Form { Smootherstep, WeightedSum } form = Form::Smootherstep;
    // smootherstep form
    double alpha = 1.0, beta = 0.8, gamma = 0.2;
    double lengthOptimal = 40, lengthMax = 100;
    // weighted-sum form
    double fillWeight = 1.0, emptyWeight = -1.0, avoidWeight = -10.0, overlapWeight = -1.0, outsideWeight = -1.0;
};

double volumeFitness(const VolumeFitnessSettings& s, const VoxelCounts& c, std::uint64_t targetVoxels, std::uint32_t genes);

/// Intersection over union of the model's voxels (outside ones included) and the fill target.
inline double voxelIoU(const VoxelCounts& c, std::uint64_t targetVoxels) {
    const double uni = double(c.occupied + c.outside + targetVoxels - c.inside);
    return uni > 0 ? double(c.inside) / uni : 0.0;
}

}  // namespace shapevo
