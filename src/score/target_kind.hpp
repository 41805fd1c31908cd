// Target kinds: what a run scores against (a volume of VDB grids, a picture seen through a
// camera, ...) as a plug-in family. Each kind lives in its own folder under score/ (volume/,
// image/) and is one entry of the table in score/target_kinds.cpp (TargetKind below). A kind owns:
//  - its settings: its reader takes the config's [target] keys it knows (and, once chosen, its
//    other sections, e.g. [camera]) and makes a TargetSettings, which run/settings.hpp holds
//    without knowing the kind;
//  - its loader (TargetSettings::load): the LoadedTarget a run scores against, with its scorer,
//    hash, description, IoU, evaluate() text and best-model outputs (best.vdb, best-overlay.png);
//  - its IoU's name and summary.json key, its export formats and the input files a run hashes.
// run/, report/ and cli/ ask the table and these interfaces and never branch on a kind.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/input_error.hpp"
#include "base/section_reader.hpp"
#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "grammar/grammar.hpp"
#include "mesh/mesh.hpp"
#include "score/check_models.hpp"
#include "score/fitness_settings.hpp"
#include "score/incremental_settings.hpp"
#include "score/scorer.hpp"

namespace shapevo {

struct TargetKind;

/// One chromosome scored as the run scores it (`shapevo evaluate`).
struct Evaluation {
    double fitness = 0;  ///< Scorer::fitness, what the search saw (summary.json's best_fitness)
    double iou = 0;      ///< the kind's IoU (summary.json's TargetKind::iouKey)
    /// One line: "fitness F  <iouKey> I  genes G  primitives P" and the kind's counts
    /// ("  inside N  occupied N ..." for a volume, "  covered N  hit N ..." for a picture),
    /// numbers as summary.json writes them.
    std::string text;
};

/// A kind's counts for Evaluation::text, each as "  name value": "  inside 12  occupied 30 ...".
struct NamedCount {
    const char* name;
    std::uint64_t value;
};
std::string countsText(std::initializer_list<NamedCount> counts);

/// Evaluation::text from its parts; `counts` is the kind's tail ("  inside 12  occupied 30 ...").
std::string evaluationText(const TargetKind& kind, double fitness, double iou, std::uint32_t genes,
                           std::size_t primitives, const std::string& counts);

/// What loading a target needs besides the kind's own settings.
struct TargetLoadContext {
    const GenomeFamily& family;  ///< the run's model family (a kind asks it for a tree grammar or a graph family)
    const FitnessSettings& fitness;
    const IncrementalSettings& incremental;
    std::uint32_t maxPrimitives = 0;  ///< genome.max_primitives
    CheckModels checkModels;          ///< for the kind's start-up checks (a camera that sees nothing)
    std::string configPath;           ///< the file a start-up check's error names
};

/// The run's derivation-tree grammar, for a kind (or a scorer) that derives trees. @throw
/// InputError naming the config's [target] for a family without one (a 2D graph grammar).
const Grammar& requireTreeGrammar(const TargetLoadContext& context, const TargetKind& kind);

/// A target loaded for a run: its scorer, and what a run reports and writes about it. Every
/// command that scores (run, resume, evaluate, export) loads it through TargetSettings::load.
class LoadedTarget {
public:
    virtual ~LoadedTarget() = default;
    virtual const Scorer& scorer() const = 0;
    /// Hash of the target data: a run resumes only against the same target.
    std::uint64_t hash() const { return hash_; }
    /// One phrase for the start-up line, e.g. "targets/x.vdb (80x80x80 voxels, 1234 to fill)".
    const std::string& description() const { return description_; }
    /// The file a changed-target error names.
    const std::string& primaryFile() const { return primaryFile_; }
    /// What the kind chose where the config left the choice to it, for the start-up line, e.g.
    /// "cover: auto → opaque (the picture has transparency)"; empty when it chose nothing.
    const std::string& choices() const { return choices_; }
    /// hash64 of the bytes the loader read of each of TargetSettings::inputFiles(), in order (what
    /// hashFile gives): a run records its target inputs without reading them again. Empty when
    /// the kind does not keep them; the run then hashes the files itself.
    const std::vector<std::uint64_t>& inputHashes() const { return inputHashes_; }
    /// Score `c` (valid for the run's grammar) with the run's scorer, and count what it covers.
    virtual Evaluation evaluate(const Chromosome& c) const = 0;
    /// The IoU of `c` (Evaluation::iou) from one scoring pass: the progress line and the curve's
    /// iou column. `workspace` is one that scorer().makeWorkspace() made. Like every scoring, it
    /// adds to scorer().anomalies().
    virtual double iou(const Chromosome& c, ScoreWorkspace& workspace) const = 0;
    /// Score the best model again, write the kind's files of it into `folder` (best.vdb: its
    /// voxels; best-overlay.png: its silhouette against the picture) and return its IoU.
    virtual double writeBest(const Chromosome& best, const std::string& folder) const = 0;
    /// `shapevo export --format F`, F one of TargetKind::exportFormats (the caller checks).
    virtual void exportBest(const Chromosome& best, const std::string& format, const std::string& path) const = 0;
    /// `shapevo target G.genome --image CONFIG -o OUT.png`: model `c` drawn as a target of this
    /// kind, one the model reaches exactly (a picture: black where the model covers a pixel, white
    /// elsewhere, read as hit / avoid by cover "dark"). Returns the pixels covered. @throw
    /// InputError(path) for a kind that cannot (a volume: `export --format vdb` makes one).
    virtual std::uint64_t drawModelTarget(const Chromosome& c, const std::string& path) const {
        (void)c;
        throw InputError(path, "", "this target kind cannot draw a model as a target");
    }

protected:
    /// Set by the kind's constructor: hash(), description(), primaryFile(), choices(), inputHashes().
    std::uint64_t hash_ = 0;
    std::string description_, primaryFile_, choices_;
    std::vector<std::uint64_t> inputHashes_;
};

/// A kind's settings, made by its reader (TargetKind::readTarget) and finished by the table
/// (score/target_kinds.hpp, readTargetSettings) once the kind is chosen. Immutable afterwards.
class TargetSettings {
public:
    virtual ~TargetSettings() = default;
    virtual const TargetKind& kind() const = 0;
    /// Whether [target] names this kind (one of its own keys is given).
    virtual bool named() const = 0;
    /// The keys that name it ("target.image"), for the error of a [target] naming two kinds.
    virtual std::vector<std::string> namingKeys() const = 0;
    /// Once chosen: read its other sections (TargetKind::sections) and check its keys together.
    /// `missing` is the message for a [target] that names no kind at all.
    virtual void finish(ConfigReader& config, const std::string& missing) = 0;
    /// Load the target. @throw InputError on bad or missing files, or a failed start-up check.
    virtual std::unique_ptr<LoadedTarget> load(const TargetLoadContext& context) const = 0;
    /// The files a run hashes as its "target" inputs, in order.
    virtual std::vector<std::string> inputFiles() const = 0;
};

/// One target kind: one entry of the table in score/target_kinds.cpp.
struct TargetKind {
    std::string_view name;     ///< "volume", "image"
    std::string_view summary;  ///< one line for help and docs
    /// Reads the kind's own [target] keys (every kind reads its keys, so another kind's key is
    /// known, not unknown) and checks each on its own.
    std::unique_ptr<TargetSettings> (*readTarget)(SectionReader& target);
    /// Sections besides [target] the kind reads once chosen ({"camera"}); another kind's config
    /// that has one is refused.
    std::span<const std::string_view> sections;
    /// [target] keys holding a file that, given with --set, is taken from the current directory
    /// and recorded absolute ({"image"}); other paths are relative to the config file.
    std::span<const std::string_view> shellRelativeFiles;
    std::string_view noun;        ///< "a volume target", "an image target" (messages)
    std::string_view namedBy;     ///< how a config names it: "image = \"FILE.png\""
    std::string_view namingLine;  ///< one [target] line that names it, for the config reference: image = "target.png"
    std::string_view keysPhrase;  ///< its keys in "... cannot be combined with fill/avoid volumes or a grid"
    std::string_view iouName;     ///< "voxel IoU", "silhouette IoU": progress line, curve plots, final line
    std::string_view iouKey;      ///< summary.json's key for it and evaluate's: "voxel_iou", "silhouette_iou"
    /// What `shapevo export` writes of a run with this target besides meshes ({"vdb"}).
    std::span<const std::string_view> exportFormats;
    /// `shapevo target MESH --image CONFIG -o OUT`: draw a mesh as a target of this kind through
    /// the settings of a config of this kind; returns what to print. nullptr: the kind cannot.
    std::string (*drawMeshTarget)(const TargetSettings& settings, const Mesh& mesh, const std::string& meshPath,
                                  const std::string& configPath, const std::string& out) = nullptr;
};

}  // namespace shapevo
