// islandLoop: the generations of one island (this rank) with migration, global statistics,
// agreed stopping, checkpoints and the final outputs; shared by `run` and `resume`. Promises: a
// seeded sync run repeats byte for byte and resumes exactly, however often the islands meet;
// in async mode no rank waits for another except in a checkpoint and at the end.
#pragma once
#include <iosfwd>
#include <string>

#include "checkpoint/island_state.hpp"
#include "genome/genome_family.hpp"
#include "island/mpi_session.hpp"
#include "run/job_options.hpp"
#include "run/scene.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// `model` is the run's model family and grammar (run/models/loaded_model.hpp): its genome is what
/// the search, migration and genome files see. `meta` carries the run's identity and, when resuming, its curve and
/// time so far; `restored` is this rank's island from the checkpoint (null for a new run).
/// Collective. Throws RunFailure when a checkpoint cannot be written.
JobResult islandLoop(const MpiSession& mpi, const RunSettings& s, const LoadedModel& model, const Scene& scene, const std::string& folder, RunMetadata meta, const IslandState* restored,
                     const JobOptions& options, std::ostream& log);

}  // namespace shapevo
