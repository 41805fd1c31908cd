// VolumeScorer: incremental voxelization and its check (the rest of the hot path lives in the header).
#include "score/volume/volume_scorer.hpp"

#include <string>

namespace shapevo {

VoxelCounts VolumeScorer::scoreCached(Workspace& w) const {
    VoxelCounts counts;
    drawThroughCache(
        *w.cache, w.geometry.primitives, w.probes, w.runs,
        [&](const Primitive& p, std::size_t) {
            if (!Voxelizer::drawsAsFastAsReplay(p)) return false;
            w.voxelizer.add(p, w.geometry.meshes, counts);
            return true;
        },
        [&](const PrimitiveCache<VoxelRun>::Found& found, std::size_t) {
            w.voxelizer.replay(found.records);
            counts.outside += found.extra;  // voxel centres outside the grid count once per primitive
        },
        [&](const Primitive& p, std::vector<VoxelRun>& runs) -> std::uint64_t {
            const std::uint64_t outsideBefore = counts.outside;
            w.voxelizer.addRecorded(p, w.geometry.meshes, counts, runs);
            return counts.outside - outsideBefore;
        },
        [](std::span<const VoxelRun>, std::uint64_t, std::size_t) {});
    if (w.cache->full()) noteCacheFull();
    counts = w.voxelizer.countAgainst(target_, counts);
    if (checksIncremental()) {
        const VoxelCounts full = w.voxelizer.score(w.geometry, target_);
        if (full.occupied != counts.occupied || full.inside != counts.inside || full.avoided != counts.avoided ||
            full.overlap != counts.overlap || full.outside != counts.outside)
            throw IncrementalMismatch(
                "incremental voxel scoring differs from the full one: occupied/inside/avoided/overlap/outside " +
                std::to_string(counts.occupied) + "/" + std::to_string(counts.inside) + "/" + std::to_string(counts.avoided) +
                "/" + std::to_string(counts.overlap) + "/" + std::to_string(counts.outside) + " against " +
                std::to_string(full.occupied) + "/" + std::to_string(full.inside) + "/" + std::to_string(full.avoided) + "/" +
                std::to_string(full.overlap) + "/" + std::to_string(full.outside) + " (" +
                std::to_string(w.geometry.primitives.size()) + " primitives)");
    }
    return counts;
}

}  // namespace shapevo
