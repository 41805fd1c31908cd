// `shapevo evaluate CONFIG.toml FILE.genome`: score a saved chromosome against a config's target,
// as run scores it (run/scene.hpp).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "genome/genome_file.hpp"
#include "run/config_file.hpp"
#include "run/scene.hpp"

namespace shapevo {

namespace {

struct EvaluateOptions {
    std::string config;
    std::string genome;
    std::vector<std::string> sets;
};
EvaluateOptions evaluateOptions;

}  // namespace

void EvaluateCommand::addOptions(CLI::App& command) {
    EvaluateOptions& o = evaluateOptions;
    command.add_option("config", o.config, "TOML config, any that run accepts (see configs/)")->required();
    command.add_option("genome", o.genome, ".genome file (best.genome of a run, or from sample --genome)")->required();
    command.add_option("--set", o.sets, "override a config value as run --set does, e.g. --set score.form=weighted (repeatable)");
}

void EvaluateCommand::run(const CommandContext&) {
    const EvaluateOptions& o = evaluateOptions;
    const RunSettings s = loadConfig(o.config, o.sets);
    const std::unique_ptr<LoadedModel> model = LoadedModel::load(s);
    const Chromosome c = readGenome(model->family(), s.grammarPath, s.limits, o.genome);
    std::cout << Scene::load(s, *model)->evaluate(c).text << "\n";
}

}  // namespace shapevo
