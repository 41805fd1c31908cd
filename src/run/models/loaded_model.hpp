// LoadedModel: a run's model family with its grammar, loaded once from the config's grammar file
// — the model-family seam's side in run/ (the genome's side is genome/genome_family.hpp). A
// member per family: run/models/tree_model.cpp (.grammar, .rule, .pcg: derivation trees, drawn as
// meshes) and run/models/graph_model.cpp (.yml, .yaml: 2D graph grammars, drawn as SVG and PNG).
// Everything in run/ that depends on what a model is — the input files a run hashes, the formats
// `export` and `sample` write, the best model's files of a run folder, the words that describe a
// model — asks it, never the grammar's kind. It owns the grammar its family refers to, so it is
// neither copied nor moved.
#pragma once
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/atomic_write.hpp"
#include "genome/families/graph_family.hpp"
#include "genome/genome_family.hpp"
#include "report/render/model_picture.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// The best model's files of a run folder, made once (a derivation), written as jobs side by side.
class BestModelFiles {
public:
    virtual ~BestModelFiles() = default;
    /// Jobs that write the files into `folder` side by side with the run's other outputs.
    virtual void addJobs(const std::string& folder, std::vector<std::function<void()>>& jobs) const = 0;
    /// What must wait for every other output (a textured OBJ names its images after the others).
    virtual void afterJobs(const std::string& folder) const { (void)folder; }
    /// The model's size for summary.json's best_primitives (primitives; a drawing's shapes).
    virtual std::size_t size() const = 0;
};

class LoadedModel {
public:
    LoadedModel() = default;
    LoadedModel(const LoadedModel&) = delete;
    LoadedModel& operator=(const LoadedModel&) = delete;
    virtual ~LoadedModel() = default;

    /// The grammar file `s.grammarPath`, by its extension. @throw InputError on bad input.
    static std::unique_ptr<LoadedModel> load(const RunSettings& s);
    /// The same from text already read (a checkpoint's stored grammar), `path` its original path.
    static std::unique_ptr<LoadedModel> fromText(const RunSettings& s, const std::string& text, const std::string& path);

    virtual const GenomeFamily& family() const = 0;
    /// The derivation-tree grammar (null for another family).
    virtual const Grammar* tree() const { return nullptr; }
    /// The graph-derivation family (null for another family).
    virtual const GraphFamily* graph() const { return nullptr; }
    /// The grammar file's text (stored in the run folder and its checkpoints).
    virtual const std::string& source() const = 0;
    /// Files besides the grammar a run hashes as inputs: (role, path) — includes, meshes, textures.
    virtual std::vector<std::pair<std::string, std::string>> extraInputs(const std::string& grammarPath) const = 0;
    /// The formats `export` and `sample` write a model in: obj, ply, glb; svg, png.
    virtual std::span<const std::string_view> modelFormats() const = 0;
    /// Write model `c` as `format` (one of modelFormats()) to `path`. @throw InputError for
    /// another format or an existing file under Replace::Never.
    virtual void writeModel(const Chromosome& c, const std::string& format, const std::string& path, Replace replace) const = 0;
    /// Model `c`'s size in words: "12 primitives", "431 shapes".
    virtual std::string describe(const Chromosome& c) const = 0;
    /// `shapevo render`: a picture of model `c` at `path` (PNG) — a tree's mesh in `views` (named
    /// `viewName`), each `size`; a drawing at `size` (views do not apply). Returns what it drew:
    /// "800x600, three-quarter view of 4312 triangles", "800x600 drawing of 431 shapes".
    virtual std::string render(const Chromosome& c, std::span<const View> views, const std::string& viewName, PictureSize size,
                               const std::string& path) const = 0;
    /// The best model's files of a run folder.
    virtual std::unique_ptr<BestModelFiles> bestFiles(const Chromosome& best) const = 0;
};

}  // namespace shapevo
