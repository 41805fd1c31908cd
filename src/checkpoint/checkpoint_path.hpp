// Checkpoint paths: what `shapevo inspect` and `shapevo export` accept, resolved to the one
// checkpoint folder they read. Contract of resolveCheckpointPath(path):
//   - a checkpoint folder (one that holds a MANIFEST or a run.h5, or is named checkpoint-NNNNNN)
//     -> that folder, complete or not: the checkpoint reader then says what is missing;
//   - a run folder (a folder holding published checkpoint-NNNNNN/ folders) -> its newest complete
//     checkpoint;
//   - a checkpoint file, run.h5 or island-NNNN.h5, inside a checkpoint folder -> that folder (an
//     island file stands for its whole checkpoint; inspect and export read every island);
//   - anything else -> InputError(path, "", why and what is accepted): a missing path, a file that
//     is not a checkpoint file, an island file its checkpoint's MANIFEST does not list, a folder
//     without checkpoints, a run folder none of whose checkpoints is complete. The CLI exits 2.
// Only names are looked at, plus the MANIFEST (no HDF5 file is opened); a run folder's candidates
// are verified with verifyCheckpoint (checkpoint_file.hpp).
#pragma once
#include <string>

namespace shapevo {

std::string resolveCheckpointPath(const std::string& path);

}  // namespace shapevo
