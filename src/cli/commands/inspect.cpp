// `shapevo inspect RUN_DIR|CHECKPOINT|ISLAND.h5`: a checkpoint summarised in words
// (checkpoint/checkpoint_file.hpp).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/checkpoint_path.hpp"
#include "cli/commands.hpp"
#include "run/config_file.hpp"

namespace shapevo {

namespace {

struct InspectOptions {
    std::string path;
    bool verbose = false;
};
InspectOptions inspectOptions;

}  // namespace

void InspectCommand::addOptions(CLI::App& command) {
    InspectOptions& o = inspectOptions;
    command.add_option("path", o.path, kCheckpointPaths)->required();
    command.add_flag("-v,--verbose", o.verbose, "also print the config");
}

void InspectCommand::run(const CommandContext&) {
    const InspectOptions& o = inspectOptions;
    const std::string folder = resolveCheckpointPath(o.path);
    AttrOverrides attrs;  // the run's [grammar.attr], which its grammar was read with
    try {
        const RunMetadata meta = readRunMetadata(folder + "/run.h5");
        attrs = parseConfig(meta.configText, meta.configPath).grammarAttrs;
    } catch (const InputError&) {
        // describeCheckpoint reports what is wrong with the checkpoint itself
    }
    std::cout << describeCheckpoint(folder, o.verbose, attrs);
}

}  // namespace shapevo
