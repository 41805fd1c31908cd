// Scene: what a run scores against, loaded once from its settings: a volume (VDB fill/avoid
// grids baked into bit rows) or an image (a PNG target seen through a camera). It
// owns the target and the scorer, says what it is in the log, and writes the target-specific
// outputs of the best model (IoU in summary.json, the model's voxels). Every command that scores
// (run, resume, evaluate, export) loads its target through Scene::load, so all score alike.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "report/run_report.hpp"
#include "run/settings.hpp"
#include "score/scorer.hpp"
#include "score/camera.hpp"
#include "score/image_target.hpp"
#include "score/volume_target.hpp"

namespace shapevo {

class VolumeScorer;
class ImageScorer;

/// One chromosome scored as the run scores it (`shapevo evaluate`).
struct Evaluation {
    double fitness = 0;  ///< Scorer::fitness, what the search saw (summary.json's best_fitness)
    double iou = 0;      ///< voxel or silhouette IoU (summary.json's voxel_iou / silhouette_iou)
    /// One line: "fitness F  voxel_iou I  genes G  primitives P  inside ..." (volume targets) or
    /// "fitness F  silhouette_iou I  genes G  primitives P  hit ..." (image targets), numbers as
    /// summary.json writes them.
    std::string text;
};

class Scene {
public:
    /// Read the target(s) named in `s`. @throw InputError on bad or missing files.
    static std::unique_ptr<Scene> load(const RunSettings& s, const Grammar& g);
    ~Scene();

    const Scorer& scorer() const { return *scorer_; }
    /// Hash of the target data: a run resumes only against the same target.
    std::uint64_t hash() const { return hash_; }
    /// One phrase for the start-up line, e.g. "targets/x.vdb (80x80x80 voxels, 1234 to fill)".
    const std::string& description() const { return description_; }
    /// The file a changed-target error names.
    const std::string& primaryFile() const { return primaryFile_; }
    /// Score the best model again and fill the target-specific summary fields (voxel or
    /// silhouette IoU); write its target-specific files into `folder`: best.vdb (its voxels) for
    /// a volume target, best-overlay.png (silhouette against the target) for an image target.
    void reportBest(const Chromosome& best, const std::string& folder, RunSummary& summary) const;
    /// `shapevo export --format vdb|png`: the model's voxels (volume targets) or its overlay on the
    /// target (image targets). @throw InputError if the format does not fit the target kind.
    void exportBest(const Chromosome& best, const std::string& format, const std::string& path) const;
    /// Score `c` (valid for the scene's grammar) with the run's scorer, and count what it covers.
    Evaluation evaluate(const Chromosome& c) const;
    /// Voxel or silhouette IoU of `c` (Evaluation::iou), from one scoring pass: the progress line
    /// and the curve's iou column. `workspace` is one that scorer().makeWorkspace() made (kept
    /// between calls, it saves allocating the raster or voxel rows each time). Like every
    /// scoring, it adds to scorer().anomalies().
    double iou(const Chromosome& c, ScoreWorkspace& workspace) const;

private:
    Scene() = default;
    void writeOverlay(const Chromosome& best, const std::string& path, double* iou) const;

    std::optional<VolumeTarget> volume_;
    std::optional<ImageTarget> image_;
    std::optional<Camera> camera_;
    std::unique_ptr<Scorer> scorer_;
    const VolumeScorer* volumeScorer_ = nullptr;
    const ImageScorer* imageScorer_ = nullptr;
    std::uint64_t hash_ = 0;
    std::string description_, primaryFile_;
};

}  // namespace shapevo
