// The `run` and `resume` jobs: one island per MPI rank (or one island without MPI), global
// progress on rank 0, ring migration, checkpoints every checkpoint.interval generations and on
// SIGTERM/SIGUSR1, stopping rules agreed by all ranks, and the run folder's outputs:
//   config.toml, grammar copy, curve.csv, summary.json, best.obj (and best.mtl when the grammar
//   sets colours), best.ply, best.glb, best.png (a picture: report/render/model_picture.hpp), best.genome,
//   checkpoint-NNNNNN/ (HDF5, see checkpoint/checkpoint_file.hpp)
#pragma once
#include <iosfwd>
#include <string>

#include "island/mpi_session.hpp"
#include "island/together.hpp"
#include "run/job_options.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// A new run. Throws InputError (on the ranks where input was bad) or SilentFailure
/// (island/together.hpp; on the others), or RunFailure (run/job_options.hpp).
JobResult runJob(const MpiSession& mpi, const RunSettings& settings, const JobOptions& options, std::ostream& log);
/// Continue the run in `runDir` from its newest complete checkpoint.
JobResult resumeJob(const MpiSession& mpi, const std::string& runDir, const JobOptions& options, std::ostream& log);

}  // namespace shapevo
