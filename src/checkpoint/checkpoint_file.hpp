// Checkpoint files (HDF5). A checkpoint is a folder `checkpoint-NNNNNN/` (NNNNNN = generation)
// inside the run folder:
//   run.h5              RunMetadata (rank 0)
//   island-RRRR.h5      one IslandState per rank
//   MANIFEST            written last: one line per file "name size xxh3-64-hex", then "end"
// A folder is published by renaming `.checkpoint-NNNNNN.partial/` once every file is written and
// flushed; a folder without a valid MANIFEST, or whose files do not match it, is incomplete.
// The HDF5 layouts (stable names) are documented at the top of island_file.cpp and run_file.cpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "checkpoint/island_state.hpp"
#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "grammar/attr_overrides.hpp"

namespace shapevo {

/// Layout version written to every checkpoint file's schema_version attribute.
/// 4: island files hold the migrants not yet joined (/migrants); 3: the curve has an iou column
/// (2: six curve columns; 1: FNV-like checksums, before XXH3-64).
inline constexpr std::uint32_t kCheckpointSchemaVersion = 4;
/// The oldest layout still read: schema 2 files resume, their curve rows without an IoU (NaN).
inline constexpr std::uint32_t kOldestReadableSchemaVersion = 2;

// --- single files ---------------------------------------------------------------------------

/// Write `s` to `path` (HDF5), flushed and fsynced. Throws std::runtime_error on I/O failure,
/// std::invalid_argument for a state that could not be read back (fitness count differs from
/// the population size, non-finite fitness, curve evaluations above 2^53).
void writeIslandFile(const std::string& path, const IslandState& s);
/// Read an island file; checks every dataset's stored checksum and every chromosome with the
/// model family's check(). Throws InputError naming the file and the dataset on any problem.
IslandState readIslandFile(const std::string& path, const GenomeFamily& family, const GenomeLimits& limits);

/// Write run.h5, flushed and fsynced. schema_version is always kCheckpointSchemaVersion (the
/// layout this code writes), whatever m.schemaVersion says. Throws std::runtime_error on I/O
/// failure, std::invalid_argument for metadata that could not be read back (ranks < 1,
/// negative or non-finite wall time, curve evaluations above 2^53).
void writeRunMetadata(const std::string& path, const RunMetadata& m);
/// Read run.h5; checks checksums and values. Throws InputError naming the file and the dataset
/// or attribute ("/@ranks", "/config/text").
RunMetadata readRunMetadata(const std::string& path);

// --- folders ---------------------------------------------------------------------------------

std::string checkpointName(std::uint32_t generation);  ///< "checkpoint-000400"
std::string islandFileName(int rank);                  ///< "island-0003.h5"

/// Write MANIFEST in `folder` for the given file names (sizes and hashes of their bytes),
/// fsynced. Names are plain file names in `folder`. Throws std::runtime_error.
void writeManifest(const std::string& folder, const std::vector<std::string>& files);

struct ManifestEntry {
    std::string name;
    std::uint64_t size = 0;
    std::uint64_t xxh3_64 = 0;
};
/// Parse `folder`/MANIFEST (nothing else is read). A valid MANIFEST lists run.h5 and
/// island-0000.h5 ... island-(k-1).h5 for some k >= 1 (other plain file names may follow),
/// each once, then "end". Throws InputError(folder/MANIFEST, "line N", what).
std::vector<ManifestEntry> readManifest(const std::string& folder);
/// Empty if `folder` is a complete checkpoint (MANIFEST valid, every file present with the
/// listed size and hash, no file in the folder that MANIFEST does not list), else why not, naming the file ("island-0001.h5: ..."). Reads bytes
/// only: no file reaches libhdf5 before it has passed this check.
std::string verifyCheckpoint(const std::string& folder);

/// True if `folder`'s MANIFEST is valid and lists `name` with the size and hash the file has now
/// (only that file is read).
bool listedFileIsIntact(const std::string& folder, const std::string& name);

/// Published checkpoint folders of a run (full paths of folders named checkpoint-NNNNNN, six or
/// more digits), newest (highest generation) first. Empty if `runDir` does not exist.
std::vector<std::string> listCheckpoints(const std::string& runDir);
/// Remove all but the newest `keep` published checkpoints of run `runId` (keep < 1 counts as 1,
/// so the newest is never removed), and any stale `.checkpoint-*.partial` (and
/// `.checkpoint-*.replaced`) folders. A checkpoint that is not provably run `runId`'s (another
/// run's, or unreadable) is never removed. Call it after publishing, while no checkpoint is being
/// written. Best effort: what cannot be removed is left.
void pruneCheckpoints(const std::string& runDir, int keep, const std::string& runId);
/// Publish a written checkpoint: fsync `partialFolder`, rename it to `finalFolder`, fsync the
/// parent folder. If `finalFolder` exists (a damaged checkpoint of the same generation that a
/// resume went back past, or a repeat of it), it is moved aside first and deleted after the new
/// one is published, unless it is a complete checkpoint of another run than `runId`: that one is
/// never replaced (std::runtime_error naming it). Throws std::runtime_error.
void publishCheckpoint(const std::string& partialFolder, const std::string& finalFolder, const std::string& runId);

/// A human summary of a checkpoint folder (what `shapevo inspect` prints): generation, islands,
/// seed, schema, target hash, per island its individuals, best/mean fitness, genes, curve length
/// and file size; verbose adds the config text. Verifies the folder first and reads every file
/// (the grammar is the one stored in run.h5). Throws InputError if the checkpoint is incomplete
/// or any file is invalid.
/// `attrs`: the run config's [grammar.attr] values, which the stored grammar is read with.
std::string describeCheckpoint(const std::string& folder, bool verbose, const AttrOverrides& attrs = {});

}  // namespace shapevo
