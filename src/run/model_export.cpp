// Model export: mesh files, and the best model of a checkpoint in any format.
#include "run/model_export.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "base/input_error.hpp"
#include "base/word_list.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "genome/families/tree_family.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "mesh/glb_writer.hpp"
#include "report/model_writer.hpp"
#include "report/run_report.hpp"
#include "run/config_file.hpp"
#include "run/scene.hpp"
#include "score/target_kinds.hpp"

namespace shapevo {

std::string formatOfPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return ext;
}

std::vector<std::string_view> exportFormats() {
    std::vector<std::string_view> formats(kModelFormats.begin(), kModelFormats.end());
    std::vector<std::string_view> more = targetExportFormats();
    more.insert(more.end(), kDrawingFormats.begin(), kDrawingFormats.end());
    for (std::string_view f : more)
        if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
    return formats;
}

std::string formatList(std::span<const std::string_view> formats) {
    return wordList(formats.size(), [&](std::size_t i) { return formats[i]; });
}

std::string requireOutputFormat(const std::string& path, std::span<const std::string_view> accepted,
                                const std::string& option, const std::string& requested) {
    const std::string takes =
        option + " takes a " + wordList(accepted.size(), [&](std::size_t i) { return "." + std::string(accepted[i]); }) + " file";
    const std::string format = formatOfPath(path);
    if (format.empty()) throw InputError(path, "", "has no file extension; " + takes);
    if (std::find(accepted.begin(), accepted.end(), format) == accepted.end())
        throw InputError(path, "", "unknown output extension '." + shortened(format) + "'; " + takes);
    if (!requested.empty() && requested != format)
        throw InputError(path, "", "--format " + shortened(requested) + " does not match the file's extension ." + format);
    return format;
}

void writeModelFile(const Geometry& geometry, const std::string& format, const std::string& path, Replace replace) {
    if (format == "obj") writeObj(meshOf(geometry), path, replace);
    else if (format == "ply") writePly(meshOf(geometry), path, replace);
    else if (format == "glb") writeGlb(meshOf(geometry), path, replace);
    else throw InputError(path, "", "unknown model format '" + format + "' (expected obj, ply or glb)");
}

CheckpointBest bestOfCheckpoint(const std::string& folder) {
    if (const std::string problem = verifyCheckpoint(folder); !problem.empty())
        throw InputError(folder, "", "not a complete checkpoint: " + problem);
    const RunMetadata meta = readRunMetadata(folder + "/run.h5");
    RunSettings settings = parseConfig(meta.configText, meta.configPath);
    CheckpointBest b{std::move(settings), nullptr, {}, {}};
    b.model = LoadedModel::fromText(b.settings, meta.grammarText, meta.grammarPath);
    const GenomeFamily& family = b.model->family();
    double bestFitness = -INFINITY;
    for (int r = 0; r < meta.ranks; ++r) {
        const IslandState island = readIslandFile(folder + "/" + islandFileName(r), family, b.settings.limits);
        const std::size_t i = island.population.best();
        if (island.population.fitness[i] > bestFitness) {
            bestFitness = island.population.fitness[i];
            b.best = island.population.individuals[i];
            b.from = "island " + std::to_string(r) + ", fitness " + formatDouble(bestFitness);
        }
    }
    return b;
}

std::string exportCheckpointBest(const CheckpointBest& b, std::string format, const std::string& path) {
    if (format.empty()) format = formatOfPath(path);
    const std::span<const std::string_view> own = b.model->modelFormats();
    const std::vector<std::string_view> all = exportFormats();
    if (std::find(own.begin(), own.end(), format) != own.end())  // the family's own formats first (a drawing's png)
        b.model->writeModel(b.best, format, path, Replace::Never);
    else if (std::find(all.begin(), all.end(), format) != all.end())
        Scene::load(b.settings, *b.model)->exportBest(b.best, format, path);
    else throw InputError(path, "", "unknown format '" + format + "' (expected " + formatList(all) + ")");
    return "wrote " + path + " (" + b.model->describe(b.best) + "; " + b.from + ")";
}

}  // namespace shapevo
