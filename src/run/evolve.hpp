// evolve: the `shapevo run` job on one island. Loads grammar and target, runs the GA with one
// progress line per generation, and writes the run folder:
//   config.toml, grammar copy, curve.csv, summary.json, best.obj, best.ply, best.genome
#pragma once
#include <iosfwd>
#include <string>

#include "run/settings.hpp"

namespace shapevo {

struct EvolveOptions {
    bool quiet = false;  ///< no per-generation progress lines
};

struct EvolveResult {
    std::string folder;
    double bestFitness = 0;
    double voxelIoU = 0;
    std::uint64_t evaluations = 0;
    double wallSeconds = 0;
};

EvolveResult evolve(const RunSettings& settings, const EvolveOptions& options, std::ostream& log);

}  // namespace shapevo
