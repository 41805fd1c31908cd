// RunSettings: everything a run needs, read from a TOML config (run/config_file.hpp) with
// defaults from the papers. Paths are already resolved relative to the config file. Each stage
// owns its part and reads its own keys (search/, island/, checkpoint/, genome/, score/ and the
// target kinds); this struct only gathers them.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "genome/chromosome.hpp"
#include "graph/derive.hpp"
#include "checkpoint/checkpoint_settings.hpp"
#include "island/migration_settings.hpp"
#include "score/fitness_settings.hpp"
#include "score/incremental_settings.hpp"
#include "score/target_kind.hpp"
#include "search/population_settings.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

struct RunSettings {
    std::string configPath;   ///< the file it came from
    std::string configText;   ///< its text, with --set overrides applied, as stored in outputs
    std::string name = "run";
    std::uint64_t seed = 1;
    graph::DeriveLimits graphLimits;  ///< [graph]: 2D graph grammar derivations
    int threads = 0;          ///< 0 = all hardware threads
    std::string out;          ///< output folder; empty = runs/<name>[-N]
    double wallTime = 0;      ///< stop (with a checkpoint) after this many seconds; 0 = no limit
    bool generationsGiven = false;  ///< ga.generations was given (config, --set, resume --generations): run/run_limit.hpp
    std::optional<double> targetFitness;  ///< stop when the best fitness of any island reaches it

    std::string grammarPath;
    std::map<std::string, double> grammarAttrs;  ///< [grammar.attr]: values replacing the grammar's attrs
    /// [target] (and [camera]): the settings of the target kind the config names, made by the
    /// kind's reader (score/target_kinds.hpp); run/ uses it only through its interface.
    std::shared_ptr<const TargetSettings> target;

    FitnessSettings fitness;  ///< [score] form and weights
    IncrementalSettings incremental;  ///< [score] incremental, cache_mb, check_incremental
    GenomeLimits limits;
    SearchSettings search;  ///< which method runs ([search])
    PopulationSettings population;  ///< [ga] population, generations (settled by run/run_limit.hpp), initial lengths: every method's sizes
    GaSettings ga;                  ///< [ga] elitism, tournament, mutation, operator weights: the GA's and the hybrid's
    MigrationSettings migration;
    CheckpointSettings checkpoint;
};

}  // namespace shapevo
