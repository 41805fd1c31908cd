// What a `run` or `resume` job is asked (JobOptions) and what it gives back (JobResult, or
// RunFailure when a fault that is not bad input stops it). Shared by the jobs' set-up
// (run/run_job.hpp) and their island loop (run/island_loop.hpp).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shapevo {

struct JobOptions {
    bool quiet = false;                         ///< no per-generation progress lines
    std::optional<std::uint32_t> generations;   ///< resume: new generation limit (as ga.generations)
    std::optional<double> wallTime;             ///< resume: new wall time of the whole run, seconds (as run.wall_time)
    bool allowChangedInputs = false;            ///< resume: accept inputs whose files changed
    std::vector<std::string> changedInputs;     ///< resume: those that did (for summary.json)
};

struct JobResult {
    std::string folder;
    double bestFitness = 0;
    double iou = 0;               ///< voxel or silhouette IoU of the best model
    std::uint64_t evaluations = 0;
    double wallSeconds = 0;
    bool stoppedBySignal = false;
};

/// Thrown on every rank when the run must stop for a fault that is not bad input (a checkpoint
/// that cannot be written): exit 1; `message` (set on rank 0 only) says what and which
/// checkpoint is the newest complete one.
struct RunFailure {
    std::string message;
};

}  // namespace shapevo
