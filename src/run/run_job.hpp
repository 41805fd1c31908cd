// The `run` and `resume` jobs: one island per MPI rank (or one island without MPI), global
// progress on rank 0, ring migration, checkpoints every checkpoint.interval generations and on
// SIGTERM/SIGUSR1, stopping rules agreed by all ranks, and the run folder's outputs:
//   config.toml, grammar copy, curve.csv, summary.json, best.obj (and best.mtl when the grammar
//   sets colours), best.ply, best.glb, best.png (a picture: report/render/model_picture.hpp), best.genome,
//   checkpoint-NNNNNN/ (HDF5, see checkpoint/checkpoint_file.hpp)
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "island/mpi_session.hpp"
#include "run/settings.hpp"

namespace shapevo {

struct JobOptions {
    bool quiet = false;                         ///< no per-generation progress lines
    std::optional<std::uint32_t> generations;   ///< resume: new generation limit
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

/// A new run. Throws InputError (on the ranks where input was bad) or SilentFailure.
JobResult runJob(const MpiSession& mpi, const RunSettings& settings, const JobOptions& options, std::ostream& log);
/// Continue the run in `runDir` from its newest complete checkpoint.
JobResult resumeJob(const MpiSession& mpi, const std::string& runDir, const JobOptions& options, std::ostream& log);

/// Thrown on ranks whose input was fine when another rank's was not: exit 2 without a message.
struct SilentFailure {};

/// Thrown on every rank when the run must stop for a fault that is not bad input (a checkpoint
/// that cannot be written): exit 1; `message` (set on rank 0 only) says what and which
/// checkpoint is the newest complete one.
struct RunFailure {
    std::string message;
};

}  // namespace shapevo
