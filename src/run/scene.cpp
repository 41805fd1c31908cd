// Scene: target loading and the best model's target-specific report.
#include "run/scene.hpp"

#include "io/input_error.hpp"
#include "io/model_volume.hpp"
#include "io/vdb_target_file.hpp"
#include "score/volume_scorer.hpp"

namespace shapevo {

Scene::~Scene() = default;

std::unique_ptr<Scene> Scene::load(const RunSettings& s, const Grammar& g) {
    std::unique_ptr<Scene> scene(new Scene);
    scene->volume_ = loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr);
    const VolumeTarget& t = *scene->volume_;
    auto scorer = std::make_unique<VolumeScorer>(g, t, s.fitness);
    scene->volumeScorer_ = scorer.get();
    scene->scorer_ = std::move(scorer);
    scene->hash_ = t.hash;
    scene->primaryFile_ = s.targets.front().path;
    scene->description_ = s.targets.front().path + " (" + std::to_string(t.grid.nx) + "x" + std::to_string(t.grid.ny) + "x" +
                          std::to_string(t.grid.nz) + " voxels, " + std::to_string(t.fillCount) + " to fill)";
    return scene;
}

void Scene::reportBest(const Chromosome& best, const std::string& folder, RunSummary& summary) const {
    VolumeScorer::Workspace ws(volume_->grid);
    VoxelCounts counts;
    volumeScorer_->fitness(best, ws, &counts);
    summary.voxelIoU = voxelIoU(counts, volume_->fillCount);
    writeModelVdb(ws.geometry, volume_->grid, folder + "/best.vdb");
}

void Scene::exportBest(const Chromosome& best, const std::string& format, const std::string& path) const {
    if (format != "vdb") throw InputError(path, "", "a volume target's run exports obj, ply, glb or vdb, not " + format);
    VolumeScorer::Workspace ws(volume_->grid);
    volumeScorer_->fitness(best, ws, nullptr);
    writeModelVdb(ws.geometry, volume_->grid, path);
}

}  // namespace shapevo
