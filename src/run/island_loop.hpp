// islandLoop: the generations of one island (this rank) with migration, global statistics,
// agreed stopping, checkpoints and the final outputs; shared by `run` and `resume`. Promises: a
// seeded sync run repeats byte for byte and resumes exactly, however often the islands meet;
// in async mode no rank waits for another except in a checkpoint and at the end.
#pragma once
#include <exception>
#include <iosfwd>

#include "checkpoint/island_state.hpp"
#include "base/input_error.hpp"
#include "run/run_job.hpp"
#include "run/scene.hpp"

namespace shapevo {

/// Run `f` on every rank; if it threw InputError anywhere, every rank leaves: the failing ranks
/// rethrow (only rank 0 when it failed too, so a shared mistake is reported once), the others
/// throw SilentFailure.
template <class F>
void together(const MpiSession& mpi, F&& f) {
    std::exception_ptr error;
    try {
        f();
    } catch (const InputError&) {
        error = std::current_exception();
    }
    if (mpi.allTrue(!error)) return;
    const bool rootFailed = !mpi.fromRoot(!error);
    if (error && (mpi.rank() == 0 || !rootFailed)) std::rethrow_exception(error);
    throw SilentFailure{};
}

/// `meta` carries the run's identity and, when resuming, its curve and time so far; `restored`
/// is this rank's island from the checkpoint (null for a new run).
JobResult islandLoop(const MpiSession& mpi, const RunSettings& s, const Grammar& grammar, const Scene& scene,
                     const std::string& folder, RunMetadata meta, const IslandState* restored, const JobOptions& options,
                     std::ostream& log);

}  // namespace shapevo
