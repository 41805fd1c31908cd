// Volume fitness forms; see volume_fitness.hpp for the formulas and their sources.
#include "score/volume/volume_fitness.hpp"

namespace shapevo {

double volumeFitness(const FitnessSettings& s, const VoxelCounts& c, std::uint64_t targetVoxels, std::uint32_t genes) {
    const double notFill = double(c.occupied - c.inside);
    if (s.form == FitnessSettings::Form::Smootherstep) {
        const double t = double(targetVoxels);
        return s.alpha * smootherstep(double(c.inside), 0.0, t) -
               s.beta * smootherstep(notFill + double(c.overlap) + double(c.outside), 0.0, 2.0 * t) -
               s.gamma * smootherstep(double(genes), s.lengthOptimal, s.lengthMax);
    }
    const double empty = notFill - double(c.avoided);
    return s.fillWeight * double(c.inside) + s.emptyWeight * empty + s.avoidWeight * double(c.avoided) +
           s.overlapWeight * double(c.overlap) + s.outsideWeight * double(c.outside);
}

}  // namespace shapevo
