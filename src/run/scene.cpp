// Scene: the start-up check every kind shares, loading through the kind, and the best model's report.
#include "run/scene.hpp"

#include <algorithm>

#include "base/input_error.hpp"
#include "genome/families/tree_family.hpp"
#include "run/model_export.hpp"

namespace shapevo {

Scene::~Scene() = default;

namespace {

/// A grammar whose every model has a non-finite or absurd coordinate (a division by zero, the
/// square root of a negative, `scale 1e30`) can never give a usable best: refuse it up front,
/// naming the rule, rather than evolve to the end.
void requireFiniteModels(const CheckModels& models, const RunSettings& s, const Grammar& g) {
    Geometry geometry;
    DeriveScratch scratch;
    const TreeFamily family(g);
    if (models.any(family, [&](const Chromosome& c) {
            return derive(g, c, geometry, scratch, s.limits.maxPrimitives) != DeriveStatus::NonFinite;
        }))
        return;
    const Rule& r = g.rules[scratch.badRule];  // the last model's
    throw InputError(g.path, "line " + std::to_string(r.where.line) + " (rule " + r.name + ")",
                     "every one of " + std::to_string(CheckModels::kCount) +
                         " random models has a primitive with a non-finite coordinate or one beyond 1e6 (last seen in "
                         "this rule); look for a division by zero, the square root of a negative number or a huge scale");
}

}  // namespace

std::unique_ptr<Scene> Scene::load(const RunSettings& s, const LoadedModel& model) { return loadFor(s, model.family()); }

std::unique_ptr<Scene> Scene::load(const RunSettings& s, const Grammar& g) {
    return loadFor(s, TreeFamily(g));  // only the load reads the family: a tree kind's scorer refers to `g`
}

std::unique_ptr<Scene> Scene::loadFor(const RunSettings& s, const GenomeFamily& family) {
    std::unique_ptr<Scene> scene(new Scene);
    const CheckModels models{s.limits, s.population.initialGenesMin, s.population.initialGenesMax};
    if (const Grammar* g = family.treeGrammar()) requireFiniteModels(models, s, *g);
    scene->kind_ = &s.target->kind();
    scene->target_ = s.target->load({family, s.fitness, s.incremental, s.limits.maxPrimitives, models, s.configPath});
    return scene;
}

void Scene::reportBest(const Chromosome& best, const std::string& folder, RunSummary& summary) const {
    summary.iou = target_->writeBest(best, folder);
    summary.iouKey = std::string(kind_->iouKey);
}

void Scene::exportBest(const Chromosome& best, const std::string& format, const std::string& path) const {
    const auto& formats = kind_->exportFormats;
    if (std::find(formats.begin(), formats.end(), format) == formats.end()) {
        std::vector<std::string_view> accepted(kModelFormats.begin(), kModelFormats.end());
        accepted.insert(accepted.end(), formats.begin(), formats.end());
        throw InputError(path, "", std::string(kind_->noun) + "'s run exports " + formatList(accepted) + ", not " + format);
    }
    target_->exportBest(best, format, path);
}

}  // namespace shapevo
