// Scene: what a run scores against, loaded once from its settings through the target kind the
// config names (score/target_kinds.hpp: a volume, a picture, ...). It refuses a grammar whose
// every model is unusable, owns the loaded target and its scorer, says what it is in the log, and
// writes the kind's outputs of the best model (its IoU in summary.json under the kind's key, its
// files). Every command that scores (run, resume, evaluate, export) loads its target through
// Scene::load, so all score alike. It never branches on a kind: it asks the kind's entry and
// its LoadedTarget.
#pragma once
#include <memory>
#include <string>

#include "report/run_report.hpp"
#include "run/models/loaded_model.hpp"
#include "run/settings.hpp"
#include "score/scorer.hpp"
#include "score/target_kind.hpp"

namespace shapevo {

class Scene {
public:
    /// Read the target named in `s`. @throw InputError on bad or missing files.
    static std::unique_ptr<Scene> load(const RunSettings& s, const LoadedModel& model);
    /// The same for a derivation-tree grammar held elsewhere (tests, benchmarks): its scorer
    /// refers to `g`, which must outlive the scene.
    static std::unique_ptr<Scene> load(const RunSettings& s, const Grammar& g);
    ~Scene();

    /// The target's kind: its IoU's name and key, its export formats.
    const TargetKind& kind() const { return *kind_; }
    const Scorer& scorer() const { return target_->scorer(); }
    /// Hash of the target data: a run resumes only against the same target.
    std::uint64_t hash() const { return target_->hash(); }
    /// One phrase for the start-up line, e.g. "targets/x.vdb (80x80x80 voxels, 1234 to fill)".
    const std::string& description() const { return target_->description(); }
    /// The file a changed-target error names.
    const std::string& primaryFile() const { return target_->primaryFile(); }
    /// What the target's kind chose for the user, for the start-up line ("cover: auto → opaque
    /// (the picture has transparency)"); empty when nothing.
    const std::string& choices() const { return target_->choices(); }
    /// The hashes of the target files as the kind read them (LoadedTarget::inputHashes; may be
    /// empty).
    const std::vector<std::uint64_t>& targetInputHashes() const { return target_->inputHashes(); }
    /// Score the best model again and fill the summary's IoU (and its key); write the kind's files
    /// of it into `folder` (best.vdb for a volume, best-overlay.png for a picture).
    void reportBest(const Chromosome& best, const std::string& folder, RunSummary& summary) const;
    /// `shapevo export --format F`: F one of the kind's export formats (vdb: the model's voxels;
    /// png: its overlay on the picture). @throw InputError if the format does not fit the kind.
    void exportBest(const Chromosome& best, const std::string& format, const std::string& path) const;
    /// Score `c` (valid for the scene's grammar) with the run's scorer, and count what it covers.
    Evaluation evaluate(const Chromosome& c) const { return target_->evaluate(c); }
    /// The kind's IoU of `c` (Evaluation::iou), from one scoring pass: the progress line and the
    /// curve's iou column. `workspace` is one that scorer().makeWorkspace() made (kept between
    /// calls, it saves allocating the raster or voxel rows each time). Like every scoring, it
    /// adds to scorer().anomalies().
    double iou(const Chromosome& c, ScoreWorkspace& workspace) const { return target_->iou(c, workspace); }
    /// Model `c` drawn as a target of the scene's kind at `path` (LoadedTarget::drawModelTarget).
    std::uint64_t drawModelTarget(const Chromosome& c, const std::string& path) const { return target_->drawModelTarget(c, path); }

private:
    Scene() = default;
    static std::unique_ptr<Scene> loadFor(const RunSettings& s, const GenomeFamily& family);

    const TargetKind* kind_ = nullptr;
    std::unique_ptr<LoadedTarget> target_;
};

}  // namespace shapevo
