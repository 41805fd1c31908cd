// `shapevo export RUN_DIR|CHECKPOINT|ISLAND.h5 --best -o FILE`: the best model of a checkpoint as a
// model file, or as what only the run's scene can make (run/model_export.hpp).
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "checkpoint/checkpoint_path.hpp"
#include "cli/commands.hpp"
#include "run/command_options.hpp"
#include "run/model_export.hpp"

namespace shapevo {

namespace {

struct ExportOptions {
    std::string path;
    std::string out;
    bool best = false;
    std::string format;
};
ExportOptions exportOptions;

}  // namespace

void ExportCommand::addOptions(CLI::App& command) {
    ExportOptions& o = exportOptions;
    command.add_option("path", o.path, kCheckpointPaths)->required();
    command.add_flag("--best", o.best, "the best individual over all islands (the only choice for now)")->required();
    command.add_option("-o,--output", o.out, "output file (.obj, .ply, .glb, .vdb or .png); must not exist")->required();
    command.add_option("--format", o.format,
                       "obj, ply, glb (the model), vdb (its voxels on a volume target's grid) or png (its silhouette "
                       "over an image target); must match the output file's extension")
        ->check(CLI::IsMember([] {
            const std::vector<std::string_view> formats = exportFormats();  // meshes and every target kind's
            return std::vector<std::string>(formats.begin(), formats.end());
        }()));
}

void ExportCommand::run(const CommandContext&) {
    const ExportOptions& o = exportOptions;
    requireOutputFormat(o.out, exportFormats(), "-o", o.format);
    refuseExisting(o.out);
    std::cout << exportCheckpointBest(bestOfCheckpoint(resolveCheckpointPath(o.path)), o.format, o.out) << "\n";
}

}  // namespace shapevo
