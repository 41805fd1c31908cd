// The volume target kind: its reader, its loaded target (scorer, IoU, best.vdb) and its entry.
#include "score/volume/volume_kind.hpp"

#include <array>
#include <limits>

#include "base/input_error.hpp"
#include "score/volume/model_volume.hpp"
#include "score/volume/volume_scorer.hpp"

namespace shapevo {

namespace {

class LoadedVolume final : public LoadedTarget {
public:
    LoadedVolume(const VolumeTargetSettings& s, const TargetLoadContext& c)
        : target_(loadVolumeTarget(s.targets, s.grid ? &*s.grid : nullptr)), scorer_(requireTreeGrammar(c, volumeTargetKind), target_, c.fitness) {
        scorer_.setMaxPrimitives(c.maxPrimitives);
        scorer_.setIncremental(c.incremental.cacheBytes(), c.incremental.check);
        hash_ = target_.hash;
        inputHashes_ = target_.fileHashes;  // inputFiles() lists the same specs in the same order
        primaryFile_ = s.targets.front().path;
        description_ = s.targets.front().path + " (" + std::to_string(target_.grid.nx) + "x" + std::to_string(target_.grid.ny) +
                       "x" + std::to_string(target_.grid.nz) + " voxels, " + std::to_string(target_.fillCount) + " to fill)";
    }
    const Scorer& scorer() const override { return scorer_; }

    Evaluation evaluate(const Chromosome& c) const override {
        Evaluation e;
        e.fitness = scorer_.fitness(c, *scorer_.makePlainWorkspace());
        VolumeScorer::Workspace ws(target_.grid);
        VoxelCounts n;
        scorer_.fitness(c, ws, &n);
        e.iou = voxelIoU(n, target_.fillCount);
        e.text = evaluationText(volumeTargetKind, e.fitness, e.iou, c.genes, ws.geometry.primitives.size(),
                                countsText({{"inside", n.inside}, {"occupied", n.occupied}, {"avoided", n.avoided},
                                            {"overlap", n.overlap}, {"outside", n.outside}, {"target", target_.fillCount}}));
        return e;
    }
    double iou(const Chromosome& c, ScoreWorkspace& workspace) const override {
        VoxelCounts n;
        scorer_.fitness(c, static_cast<VolumeScorer::Workspace&>(workspace), &n);
        return voxelIoU(n, target_.fillCount);
    }
    double writeBest(const Chromosome& best, const std::string& folder) const override {
        VolumeScorer::Workspace ws(target_.grid);
        VoxelCounts counts;
        scorer_.fitness(best, ws, &counts);
        const double iou = voxelIoU(counts, target_.fillCount);
        writeModelVdb(ws.geometry, target_.grid, folder + "/best.vdb");
        return iou;
    }
    void exportBest(const Chromosome& best, const std::string&, const std::string& path) const override {
        VolumeScorer::Workspace ws(target_.grid);
        scorer_.fitness(best, ws, nullptr);
        writeModelVdb(ws.geometry, target_.grid, path);
    }

private:
    VolumeTarget target_;
    VolumeScorer scorer_;
};

constexpr std::array<std::string_view, 1> kVolumeExportFormats{"vdb"};

}  // namespace

std::unique_ptr<TargetSettings> VolumeTargetSettings::read(SectionReader& r) {
    auto s = std::make_unique<VolumeTargetSettings>();
    for (const auto& f : r.strings("fill", "volume: one VDB level set or a list of them, the voxels to fill; names the volume kind"))
        s->targets.push_back({r.resolvePath(f), false});
    for (const auto& f : r.strings("avoid", "volume: VDB level sets of voxels to leave empty"))
        s->targets.push_back({r.resolvePath(f), true});
    // Read into NaN (no default: absent means the targets' bounds and the first target's voxels),
    // kept only when given.
    constexpr double none = std::numeric_limits<double>::quiet_NaN();
    glm::dvec3 lo(none), hi(none);
    double voxelSize = none;
    s->hasMin_ = r.vec("grid_min", lo,
                       "volume: the lower corner of an explicit dense grid (with grid_max and voxel_size); default: "
                       "the targets' bounds padded by 25 % on every side");
    s->hasMax_ = r.vec("grid_max", hi, "volume: the upper corner of the explicit grid");
    r.number("voxel_size", voxelSize, 1e-6, 1e6,
             "volume: the explicit grid's voxel size (default: the first target's)");
    s->hasVoxelSize_ = r.has("voxel_size");
    if (s->hasMin_) s->gridKeys_.min = lo;
    if (s->hasMax_) s->gridKeys_.max = hi;
    if (s->hasVoxelSize_) s->gridKeys_.voxelSize = voxelSize;
    return s;
}

bool VolumeTargetSettings::named() const { return !targets.empty() || hasMin_ || hasMax_ || hasVoxelSize_; }

std::vector<std::string> VolumeTargetSettings::namingKeys() const {
    return {"target.fill", "target.avoid", "target.grid_min", "target.grid_max", "target.voxel_size"};
}

void VolumeTargetSettings::finish(ConfigReader& config, const std::string& missing) {
    SectionReader& r = config.section("target");
    if (targets.empty() || targets.front().avoid) r.failKeys({"target.fill", "target.avoid"}, "", missing);
    if (hasMin_ != hasMax_ || (hasMin_ && gridKeys_.voxelSize <= 0) || (!hasMin_ && hasVoxelSize_))
        r.failKeys({"target.grid_min", "target.grid_max", "target.voxel_size"}, "[target]",
                   "grid_min, grid_max and voxel_size must be given together");
    if (hasMin_) grid = gridKeys_;
}

std::unique_ptr<LoadedTarget> VolumeTargetSettings::load(const TargetLoadContext& context) const {
    return std::make_unique<LoadedVolume>(*this, context);
}

std::vector<std::string> VolumeTargetSettings::inputFiles() const {
    std::vector<std::string> files;
    for (const TargetVolumeSpec& t : targets) files.push_back(t.path);
    return files;
}

const TargetKind volumeTargetKind{
    .name = "volume",
    .summary = "OpenVDB level sets to fill and to avoid, scored on dense voxel rows (the default)",
    .readTarget = VolumeTargetSettings::read,
    .sections = {},
    .shellRelativeFiles = {},
    .noun = "a volume target",
    .namedBy = "fill = \"FILE.vdb\" (at least one fill target)",
    .namingLine = "fill = \"target.vdb\"",
    .keysPhrase = "fill/avoid volumes or a grid",
    .iouName = "voxel IoU",
    .iouKey = "voxel_iou",
    .exportFormats = kVolumeExportFormats,
};

}  // namespace shapevo
