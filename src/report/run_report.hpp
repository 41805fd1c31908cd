// Run reports: the fitness curve (curve.csv) and the run summary (summary.json).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "search/generation_stats.hpp"
#include "base/format_double.hpp"  // formatDouble, for the reports' users

namespace shapevo {

struct RunSummary {
    std::string name, config, grammar;
    std::uint64_t seed = 0;
    std::uint32_t generations = 0;
    std::uint64_t evaluations = 0;
    double wallSeconds = 0;
    double bestFitness = 0;
    /// The best model's IoU under its target kind's key (TargetKind::iouKey: "voxel_iou",
    /// "silhouette_iou"); no key, no field.
    std::string iouKey;
    double iou = 0;
    std::uint32_t bestGenes = 0;
    std::size_t bestPrimitives = 0;
    std::uint64_t targetHash = 0;
    int threads = 0;   ///< evaluation threads per island
    int islands = 1;   ///< MPI ranks
    double migrationSeconds = 0, checkpointSeconds = 0;  ///< slowest rank's time in each
    /// Each rank's time in blocking calls with other ranks over its wall time: the slowest
    /// rank's share and the mean over ranks (0 with one island).
    double waitShareMax = 0, waitShareMean = 0;
    double waitShareOutsideCheckpointsMax = 0, waitShareOutsideCheckpointsMean = 0;  ///< the same without checkpoints
    double iouSeconds = 0;  ///< slowest rank's time scoring its best model again for the curve's IoU
    std::vector<std::string> changedInputs;  ///< inputs accepted with --allow-changed-inputs on resume
    std::uint64_t nonFiniteModels = 0;  ///< evaluations with a non-finite or absurd coordinate (worst fitness)
    std::uint64_t truncatedModels = 0;  ///< evaluations that reached genome.max_primitives
    /// Memory at the end, the largest rank's: incremental scoring's caches (all its threads),
    /// what its models keep for their children, and the process's peak resident size.
    std::uint64_t cacheBytes = 0, modelBytes = 0, maxRssBytes = 0;
    std::size_t population = 0;  ///< individuals per island
};

/// curve.csv: generation,seconds,evaluations,best,mean,std,iou (one row per generation; iou, the
/// best model's voxel or silhouette IoU, is empty where it was not measured).
void writeCurveCsv(const std::vector<GenerationStats>& curve, const std::string& path);
void writeSummaryJson(const RunSummary& s, const std::string& path);

}  // namespace shapevo
