// VolumeScorer: chromosome -> geometry -> voxel counts -> fitness, against one VolumeTarget.
// A pure function of the chromosome; each thread brings its own Workspace.
#pragma once
#include <memory>

#include "geometry/derive.hpp"
#include "score/volume_fitness.hpp"
#include "score/volume_target.hpp"
#include "score/voxelizer.hpp"

namespace shapevo {

class VolumeScorer {
public:
    struct Workspace {
        explicit Workspace(const GridSpec& grid) : voxelizer(grid) {}
        DeriveScratch derive;
        Geometry geometry;
        Voxelizer voxelizer;
    };

    VolumeScorer(const Grammar& g, const VolumeTarget& target, const VolumeFitnessSettings& settings)
        : grammar_(g), target_(target), settings_(settings) {}

    std::unique_ptr<Workspace> makeWorkspace() const { return std::make_unique<Workspace>(target_.grid); }
    double fitness(const Chromosome& c, Workspace& w, VoxelCounts* countsOut = nullptr) const {
        derive(grammar_, c, w.geometry, w.derive);
        const VoxelCounts counts = w.voxelizer.score(w.geometry.primitives, target_);
        if (countsOut) *countsOut = counts;
        return volumeFitness(settings_, counts, target_.fillCount, c.genes);
    }
    const VolumeTarget& target() const { return target_; }
    const Grammar& grammar() const { return grammar_; }

private:
    const Grammar& grammar_;
    const VolumeTarget& target_;
    VolumeFitnessSettings settings_;
};

}  // namespace shapevo
