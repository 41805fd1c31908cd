// The end of a run: the best individual of all islands and the run's totals gathered from every
// rank (collective), then rank 0's outputs in the run folder: best.png, best.obj (and best.mtl),
// best.ply, best.glb, best.genome, curve.csv/.svg/.png and the target kind's own files
// (Scene::reportBest), written side by side (base/side_by_side.hpp; a textured best.obj after the
// others, so its images take free names), then summary.json, the scorer's warnings and the
// closing line.
// Promise: the collectives run in the same order on every rank; only rank 0 writes; each file's
// bytes do not depend on the order the files are written in.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

#include "checkpoint/island_state.hpp"
#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "island/mpi_session.hpp"
#include "run/island_turn.hpp"
#include "run/job_options.hpp"
#include "run/loop_clock.hpp"
#include "run/scene.hpp"
#include "search/population.hpp"

namespace shapevo {

/// The best individual of all islands.
struct Champion {
    Chromosome chromosome;  ///< on rank 0 only
    double fitness = 0;     ///< on every rank
};

/// Collective: the best individual of all islands, sent to rank 0.
Champion gatherChampion(const MpiSession& mpi, const Population& population);

/// This rank's figures for summary.json.
struct IslandTotals {
    std::uint64_t evaluations = 0;
    Scorer::Anomalies anomalies;  ///< the search's own (not the start-up checks', not the IoU's)
    double migrationSeconds = 0, checkpointSeconds = 0, iouSeconds = 0;
    double checkpointWaitedSeconds = 0;  ///< the part of this rank's waiting spent in checkpoints
    std::uint64_t cacheBytes = 0, modelBytes = 0, peakResidentBytes = 0;
};

/// The run's figures: sums over the ranks, or the largest rank's (the slowest rank's share is
/// what the run waited for; the largest rank's memory).
struct RunTotals {
    std::uint64_t evaluations = 0, nonFiniteModels = 0, truncatedModels = 0;  ///< sums
    double migrationSeconds = 0, checkpointSeconds = 0, iouSeconds = 0;       ///< maxima
    double waitShareMax = 0, waitShareOutsideCheckpointsMax = 0;
    double waitShareSum = 0, waitShareOutsideCheckpointsSum = 0;
    std::uint64_t cacheBytes = 0, modelBytes = 0, maxRssBytes = 0;            ///< maxima
};

/// Collective: every rank's totals combined, on every rank. The waiting shares (all of it, and the
/// part outside checkpoints: async mode's promise) are read from `clock` after the first sum, so
/// they count the waiting in it.
RunTotals gatherTotals(const MpiSession& mpi, const IslandTotals& own, const LoopClock& clock);

/// What rank 0 writes the outputs from.
struct RunEnd {
    const RunSettings& s;
    const LoadedModel& model;  ///< the run's model family: best.genome and the best model's files
    const Scene& scene;
    const std::string& folder;
    const RunMetadata& meta;  ///< the run's curve and identity
    const JobOptions& options;
    Chromosome champion;
    RunTotals totals;
    std::uint32_t generation = 0;  ///< rank 0's island's
    std::size_t population = 0;    ///< individuals per island
    int threads = 0;               ///< evaluation threads per island
    int islands = 1;               ///< islands taking part (1 without MPI): the wait shares' mean
    int ranks = 1;                 ///< MPI ranks (summary.json's islands)
    StopReason stop;
};

/// Rank 0: write the run folder's outputs and the closing line (to `log` unless quiet and not
/// stopped by a signal); sets `result.iou`.
void writeRunOutputs(const RunEnd& end, JobResult& result, std::ostream& log);

}  // namespace shapevo
