// Run identity: what makes a checkpoint belong to one run and no other. A run gets a random id
// when it starts; the id, the seed, the config text and the hashes of every input file are
// stored in every checkpoint (run.h5; the id, seed and rank count in every island file too), and
// the id in the run folder's file `run-id`. A checkpoint whose identity differs from its folder's
// is another run's: resume refuses it by name, and pruning and publishing never touch it.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checkpoint/island_state.hpp"

namespace shapevo {

inline constexpr const char* kRunIdFile = "run-id";

/// 32 lowercase hex digits from std::random_device.
std::string newRunId();

/// Write `runDir`/run-id (atomically). Throws std::runtime_error / InputError on I/O failure.
void writeRunId(const std::string& runDir, const std::string& runId);
/// The id in `runDir`/run-id. @throw InputError naming the file if it is missing or malformed.
std::string readRunId(const std::string& runDir);

/// The run id stored in `checkpoint`/run.h5, if its MANIFEST lists run.h5 with the bytes it has
/// and run.h5 is readable; nullopt otherwise. Reads nothing else (not the island files).
std::optional<std::string> checkpointRunId(const std::string& checkpoint);

/// Empty if island file `island` (read by rank `rank`) belongs with run file `run`: same run id,
/// seed, island count and generation, and its own rank; else what differs, naming both values.
/// `ownPace`: the islands ran at their own pace (async migration), so an island's generation is
/// its own and run.h5's is rank 0's: the generations are not compared.
std::string islandMismatch(const IslandState& island, const RunMetadata& run, int rank, bool ownPace = false);

/// An input file and the XXH3-64 of its bytes now. @throw InputError naming it if unreadable.
InputFile hashInput(const std::string& role, const std::string& path);
/// The record of an input its loader has already read and hashed (hash64 of its bytes, as
/// hashFile gives): the same InputFile as hashInput, without reading the file again.
InputFile recordInput(const std::string& role, const std::string& path, std::uint64_t hash);
/// The inputs whose files changed (or vanished) since `inputs` was recorded, one line each:
/// "grammar /abs/part.obj changed (was 0123..., now 4567...)".
std::vector<std::string> changedInputs(const std::vector<InputFile>& inputs);

/// run.h5's /inputs/text: "<role> <16 hex> <path>" per line, and back (InputError naming `file`).
std::string formatInputs(const std::vector<InputFile>& inputs);
std::vector<InputFile> parseInputs(const std::string& text, const std::string& file);

}  // namespace shapevo
