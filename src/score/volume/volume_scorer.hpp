// VolumeScorer: chromosome -> geometry -> voxel counts -> fitness, against one VolumeTarget.
// A pure function of the chromosome; each thread brings its own Workspace.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "score/primitive_cache.hpp"
#include "score/tree_scorer.hpp"
#include "score/volume/volume_fitness.hpp"
#include "score/volume/volume_target.hpp"
#include "score/volume/voxelizer.hpp"

namespace shapevo {

class VolumeScorer final : public TreeScorer {
public:
    struct Workspace : ScoreWorkspace {
        /// cacheBytes > 0: keep the primitives' voxel rows (incremental scoring, Scorer::setIncremental).
        explicit Workspace(const GridSpec& grid, std::size_t cacheBytes = 0) : voxelizer(grid) {
            // No subtree memo here: a voxel grid's scoring dwarfs derivation, and the memo's
            // first memory cost a spaceship more than it saved (docs/history/2026-12-performance-log.md,
            // "Incremental evaluation").
            if (cacheBytes > 0) cache.emplace(cacheBytes);
        }
        Voxelizer voxelizer;
        std::optional<PrimitiveCache<VoxelRun>> cache;
        std::size_t cacheBytesUsed() const override {
            return ScoreWorkspace::cacheBytesUsed() + (cache ? cache->bytesUsed() : 0);
        }
        std::vector<VoxelRun> runs;  ///< one primitive's runs, on their way into the cache
        std::vector<CacheProbe<VoxelRun>> probes;  ///< the primitives to look up, with their keys' hashes (after prefetching)
    };

    VolumeScorer(const Grammar& g, const VolumeTarget& target, const FitnessSettings& settings)
        : grammar_(g), target_(target), settings_(settings) {}

    std::unique_ptr<ScoreWorkspace> makeWorkspace() const override {
        return std::make_unique<Workspace>(target_.grid, cacheBytes());
    }
    std::unique_ptr<ScoreWorkspace> makePlainWorkspace() const override {
        return std::make_unique<Workspace>(target_.grid, 0);
    }
    double fitness(const Chromosome& c, ScoreWorkspace& w) const override {
        return fitness(c, static_cast<Workspace&>(w), nullptr);
    }
    double fitness(const Chromosome& c, Workspace& w, VoxelCounts* countsOut) const {
        if (!deriveCounted(c, w)) {
            if (countsOut) *countsOut = VoxelCounts{};
            return kWorstFitness;
        }
        const VoxelCounts counts = throughCache(w.cache, w.geometry.primitives.size()) ? scoreCached(w)
                                                                                       : w.voxelizer.score(w.geometry, target_);
        if (countsOut) *countsOut = counts;
        return volumeFitness(settings_, counts, target_.fillCount, c.genes);
    }
    const VolumeTarget& target() const { return target_; }
    const Grammar& grammar() const override { return grammar_; }

private:
    /// Voxelize and count w.geometry, replaying the runs of primitives found in w.cache and
    /// keeping the others'; with checksIncremental(), also the full way (IncrementalMismatch).
    VoxelCounts scoreCached(Workspace& w) const;

    const Grammar& grammar_;
    const VolumeTarget& target_;
    FitnessSettings settings_;
};

}  // namespace shapevo
