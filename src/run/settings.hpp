// RunSettings: everything a run needs, read from a TOML config (io/config_file.hpp) with
// defaults from the papers. Paths are already resolved relative to the config file.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "genome/chromosome.hpp"
#include "io/vdb_target_file.hpp"
#include "score/camera.hpp"
#include "score/image_target.hpp"
#include "score/volume_fitness.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

struct GaSettings {
    std::uint32_t population = 200;
    std::uint32_t generations = 50;
    std::uint32_t elitism = 30;
    std::uint32_t tournament = 10;
    double mutation = 0.30;                             ///< probability that a pair is mutated, not crossed
    double growWeight = 1.0, cutWeight = 1.0, alterWeight = 1.0;  ///< split of the mutations
    int crossoverRetries = 3;
    std::uint32_t initialGenesMin = 2, initialGenesMax = 40;  ///< initial length drawn uniformly in between
};

/// Ring migration between islands (one island per MPI rank).
struct MigrationSettings {
    std::uint32_t interval = 20;  ///< generations between migrations (0 = never)
    std::uint32_t count = 5;      ///< best individuals sent to rank + 1, replacing its worst
    bool async = false;           ///< non-blocking messages (not repeatable) instead of lock-step
};

struct CheckpointSettings {
    std::uint32_t interval = 500;  ///< generations between checkpoints (0 = none by count)
    double seconds = 300;          ///< also checkpoint when this long has passed since the last (0 = never by time)
    int keep = 3;                  ///< newest published checkpoints to keep
};

/// An image target: a PNG whose pixels are classified by `rule`, seen through `camera`.
struct ImageSceneSettings {
    std::string png;
    PixelRule rule;
    CameraSpec camera;
};

struct RunSettings {
    std::string configPath;   ///< the file it came from
    std::string configText;   ///< its text, with --set overrides applied, as stored in outputs
    std::string name = "run";
    std::uint64_t seed = 1;
    int threads = 0;          ///< 0 = all hardware threads
    std::string out;          ///< output folder; empty = runs/<name>[-N]
    double wallTime = 0;      ///< stop (with a checkpoint) after this many seconds; 0 = no limit
    std::optional<double> targetFitness;  ///< stop when the best fitness of any island reaches it

    std::string grammarPath;
    std::vector<TargetVolumeSpec> targets;   ///< volume targets (empty for an image target)
    std::optional<GridOverride> grid;
    std::optional<ImageSceneSettings> image;  ///< image target instead of volumes

    VolumeFitnessSettings fitness;
    GenomeLimits limits;
    SearchSettings search;  ///< which method runs ([search]); [ga] sizes apply to all
    GaSettings ga;
    MigrationSettings migration;
    CheckpointSettings checkpoint;
};

}  // namespace shapevo
