// IslandState and RunMetadata: everything a checkpoint holds, as plain data. The island loop
// fills them; checkpoint files (checkpoint_file.hpp) store and restore them bit for bit.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "search/generation_stats.hpp"
#include "search/population.hpp"
#include "search/population.hpp"

namespace shapevo {

/// One island (one MPI rank) at the end of a generation.
struct IslandState {
    std::string runId;                     ///< the run it belongs to (RunMetadata::runId)
    std::uint64_t seed = 0;                ///< the run's seed
    std::int32_t ranks = 1;                ///< islands in the run
    std::int32_t rank = 0;
    std::uint32_t generation = 0;          ///< generations completed
    std::uint64_t evaluations = 0;         ///< fitness evaluations on this island so far
    std::array<std::uint64_t, 4> rng{};    ///< the island's Rng state
    Population population;                 ///< chromosomes and their fitness
    Population arrivals;                   ///< sync mode: migrants received from rank - 1 that join
                                           ///< at the next migration generation (schema 4)
    std::vector<GenerationStats> curve;    ///< this island's own curve, one row per generation
};

/// One input file of a run and the XXH3-64 of its bytes when the run started.
struct InputFile {
    std::string role;  ///< "config", "grammar", "mesh", "texture", "target"
    std::string path;  ///< absolute
    std::uint64_t hash = 0;
    friend bool operator==(const InputFile&, const InputFile&) = default;
};

/// The run as a whole; written once per checkpoint by rank 0. runId, seed, configText and
/// inputs are the run's identity: fixed when it starts, the same in every checkpoint.
struct RunMetadata {
    std::string runId;                     ///< 32 random hex digits, made when the run starts
    std::uint32_t schemaVersion = 4;      ///< as read (kCheckpointSchemaVersion when written)
    std::uint64_t seed = 0;
    std::uint32_t generation = 0;          ///< generations completed by every island
    std::int32_t ranks = 1;                ///< number of islands
    double wallSeconds = 0;                ///< run time so far, summed over resumes
    std::uint64_t targetHash = 0;
    std::string name;
    std::string configPath, configText;    ///< the config (with --set overrides applied)
    std::string grammarPath, grammarText;
    std::vector<InputFile> inputs;         ///< every input file and its hash at the start
    std::vector<GenerationStats> curve;    ///< the global curve (best/mean/std over all islands)
};

}  // namespace shapevo
