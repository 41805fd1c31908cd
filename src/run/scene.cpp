// Scene: target loading and the best model's target-specific report.
#include "run/scene.hpp"

#include "genome/operators.hpp"
#include "base/input_error.hpp"
#include "report/model_volume.hpp"
#include "report/overlay_image.hpp"
#include "score/image_scorer.hpp"
#include "score/vdb_target_file.hpp"
#include "score/volume_scorer.hpp"

namespace shapevo {

Scene::~Scene() = default;

namespace {

constexpr int kCheckModels = 64;

/// The start-up checks' models: `kCheckModels` random chromosomes of the run's initial sizes,
/// from a fixed seed (so a check is repeatable), given to `f` until it returns true. Returns
/// whether it did.
template <class F>
bool anyCheckModel(const RunSettings& s, const Grammar& g, F&& f) {
    Rng rng(12345);
    Chromosome c;
    for (int i = 0; i < kCheckModels; ++i) {
        growRandomLength(g, c, rng, s.limits, s.ga.initialGenesMin, s.ga.initialGenesMax);
        if (f(c)) return true;
    }
    return false;
}

/// A grammar whose every model has a non-finite or absurd coordinate (a division by zero, the
/// square root of a negative, `scale 1e30`) can never give a usable best: refuse it up front,
/// naming the rule, rather than evolve to the end.
void requireFiniteModels(const RunSettings& s, const Grammar& g) {
    Geometry geometry;
    DeriveScratch scratch;
    if (anyCheckModel(s, g, [&](const Chromosome& c) {
            return derive(g, c, geometry, scratch, s.limits.maxPrimitives) != DeriveStatus::NonFinite;
        }))
        return;
    const Rule& r = g.rules[scratch.badRule];  // the last model's
    throw InputError(g.path, "line " + std::to_string(r.where.line) + " (rule " + r.name + ")",
                     "every one of " + std::to_string(kCheckModels) +
                         " random models has a primitive with a non-finite coordinate or one beyond 1e6 (last seen in "
                         "this rule); look for a division by zero, the square root of a negative number or a huge scale");
}

/// A camera that sees nothing makes every fitness equal and the search blind: refuse it. The
/// check models must cover at least one pixel between them.
void requireVisible(const RunSettings& s, const Grammar& g, const ImageScorer& scorer) {
    ImageScorer::Workspace ws(scorer.camera());
    if (anyCheckModel(s, g, [&](const Chromosome& c) {
            SilhouetteCounts counts;
            scorer.fitness(c, ws, &counts);
            return counts.covered > 0;
        }))
        return;
    throw InputError(s.configPath, "[camera]",
                     "sees nothing: none of " + std::to_string(kCheckModels) + " random models of " + g.path +
                         " covers a single pixel of the picture; point the camera (or the shadow's ground rectangle) at "
                         "where the grammar builds");
}
/// "800x600 pixels", or how a picture of another size was fitted: "229x304 pixels fitted
/// (contain) into 800x600 as 452x600 at (174, 0)".
std::string imagePlacement(const ImageTarget& t, TargetFit fit) {
    const auto wh = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    const TargetPlacement& p = t.placement;
    if (t.pictureWidth == t.width && t.pictureHeight == t.height && p == TargetPlacement{0, 0, t.width, t.height})
        return wh(t.width, t.height) + " pixels";
    return wh(t.pictureWidth, t.pictureHeight) + " pixels fitted (" + targetFitName(fit) + ") into " + wh(t.width, t.height) +
           " as " + wh(p.width, p.height) + " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

/// For a shadow camera whose ground rectangle was extended to square pixels: the one used.
std::string groundNote(const Camera& c) {
    if (c.projection() != Projection::Shadow || !c.groundExtended()) return "";
    return "; ground rectangle extended to the picture's aspect: [" + formatDouble(c.groundMin().x) + ", " +
           formatDouble(c.groundMin().y) + "]..[" + formatDouble(c.groundMax().x) + ", " + formatDouble(c.groundMax().y) + "]";
}
}  // namespace

std::unique_ptr<Scene> Scene::load(const RunSettings& s, const Grammar& g) {
    std::unique_ptr<Scene> scene(new Scene);
    requireFiniteModels(s, g);
    if (s.image) {
        scene->camera_ = Camera::compile(s.image->camera, s.configPath);
        scene->image_ =
            loadImageTarget(s.image->png, s.image->rule, scene->camera_->width(), scene->camera_->height(), s.image->fit,
                            s.image->scale);
        const ImageTarget& t = *scene->image_;
        auto scorer = std::make_unique<ImageScorer>(g, *scene->camera_, t, s.fitness);
        scorer->setMaxPrimitives(s.limits.maxPrimitives);
        scorer->setIncremental(s.incremental.cacheBytes(), s.incremental.check);
        scene->imageScorer_ = scorer.get();
        scene->scorer_ = std::move(scorer);
        scene->hash_ = t.hash;
        scene->primaryFile_ = s.image->png;
        const char* kind = s.image->camera.projection == Projection::Shadow ? "shadow"
                           : s.image->camera.projection == Projection::Orthographic ? "orthographic silhouette"
                                                                                      : "perspective silhouette";
        requireVisible(s, g, *scene->imageScorer_);
        scene->description_ = s.image->png + " (" + imagePlacement(t, s.image->fit) + ", " + std::to_string(t.hitCount) +
                              " to cover, " + kind + groundNote(*scene->camera_) + ")";
        return scene;
    }
    scene->volume_ = loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr);
    const VolumeTarget& t = *scene->volume_;
    auto scorer = std::make_unique<VolumeScorer>(g, t, s.fitness);
    scorer->setMaxPrimitives(s.limits.maxPrimitives);
    scorer->setIncremental(s.incremental.cacheBytes(), s.incremental.check);
    scene->volumeScorer_ = scorer.get();
    scene->scorer_ = std::move(scorer);
    scene->hash_ = t.hash;
    scene->primaryFile_ = s.targets.front().path;
    scene->description_ = s.targets.front().path + " (" + std::to_string(t.grid.nx) + "x" + std::to_string(t.grid.ny) + "x" +
                          std::to_string(t.grid.nz) + " voxels, " + std::to_string(t.fillCount) + " to fill)";
    return scene;
}

void Scene::writeOverlay(const Chromosome& best, const std::string& path, double* iou) const {
    ImageScorer::Workspace ws(*camera_);
    SilhouetteCounts counts;
    imageScorer_->fitness(best, ws, &counts);
    if (iou) *iou = silhouetteIoU(counts, image_->hitCount);
    std::vector<std::uint8_t> model, target(std::size_t(image_->width) * std::size_t(image_->height));
    imageScorer_->modelMask(best, ws, model);
    for (int y = 0; y < image_->height; ++y)
        for (int x = 0; x < image_->width; ++x)
            target[std::size_t(y) * std::size_t(image_->width) + std::size_t(x)] = image_->isHit(x, y) ? 1 : image_->isAvoid(x, y) ? 2 : 0;
    writeOverlayPng(path, image_->width, image_->height, target.data(), model.data());
}

void Scene::reportBest(const Chromosome& best, const std::string& folder, RunSummary& summary) const {
    if (image_) {
        double iou = 0;
        writeOverlay(best, folder + "/best-overlay.png", &iou);
        summary.silhouetteIoU = iou;
        return;
    }
    VolumeScorer::Workspace ws(volume_->grid);
    VoxelCounts counts;
    volumeScorer_->fitness(best, ws, &counts);
    summary.voxelIoU = voxelIoU(counts, volume_->fillCount);
    writeModelVdb(ws.geometry, volume_->grid, folder + "/best.vdb");
}

Evaluation Scene::evaluate(const Chromosome& c) const {
    Evaluation e;
    e.fitness = scorer_->fitness(c, *scorer_->makePlainWorkspace());
    const auto count = [](const char* name, std::uint64_t n) { return std::string("  ") + name + " " + std::to_string(n); };
    std::string counted;
    std::size_t primitives = 0;
    if (image_) {
        ImageScorer::Workspace ws(*camera_);
        SilhouetteCounts n;
        imageScorer_->fitness(c, ws, &n);
        e.iou = silhouetteIoU(n, image_->hitCount);
        primitives = ws.geometry.primitives.size();
        counted = count("covered", n.covered) + count("hit", n.hit) + count("avoided", n.avoided) +
                  count("target", image_->hitCount);
    } else {
        VolumeScorer::Workspace ws(volume_->grid);
        VoxelCounts n;
        volumeScorer_->fitness(c, ws, &n);
        e.iou = voxelIoU(n, volume_->fillCount);
        primitives = ws.geometry.primitives.size();
        counted = count("inside", n.inside) + count("occupied", n.occupied) + count("avoided", n.avoided) +
                  count("overlap", n.overlap) + count("outside", n.outside) + count("target", volume_->fillCount);
    }
    e.text = "fitness " + formatDouble(e.fitness) + (image_ ? "  silhouette_iou " : "  voxel_iou ") + formatDouble(e.iou) +
             "  genes " + std::to_string(c.genes) + "  primitives " + std::to_string(primitives) + counted;
    return e;
}

double Scene::iou(const Chromosome& c, ScoreWorkspace& workspace) const {
    if (image_) {
        SilhouetteCounts n;
        imageScorer_->fitness(c, static_cast<ImageScorer::Workspace&>(workspace), &n);
        return silhouetteIoU(n, image_->hitCount);
    }
    VoxelCounts n;
    volumeScorer_->fitness(c, static_cast<VolumeScorer::Workspace&>(workspace), &n);
    return voxelIoU(n, volume_->fillCount);
}

void Scene::exportBest(const Chromosome& best, const std::string& format, const std::string& path) const {
    if (image_) {
        if (format != "png") throw InputError(path, "", "an image target's run exports obj, ply, glb or png, not " + format);
        writeOverlay(best, path, nullptr);
        return;
    }
    if (format != "vdb") throw InputError(path, "", "a volume target's run exports obj, ply, glb or vdb, not " + format);
    VolumeScorer::Workspace ws(volume_->grid);
    volumeScorer_->fitness(best, ws, nullptr);
    writeModelVdb(ws.geometry, volume_->grid, path);
}

}  // namespace shapevo
