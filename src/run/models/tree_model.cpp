// The derivation-tree family's LoadedModel (tree_model.hpp).
#include "run/models/tree_model.hpp"

#include <array>
#include <filesystem>

#include "base/input_error.hpp"
#include "genome/families/tree_family.hpp"
#include "geometry/derive.hpp"
#include "grammar/front_ends.hpp"
#include "mesh/glb_writer.hpp"
#include "report/model_writer.hpp"
#include "report/render/model_picture.hpp"
#include "run/model_export.hpp"

namespace shapevo {

namespace {

/// best.png, best.ply, best.glb and best.obj of one derived model.
class TreeBestFiles final : public BestModelFiles {
public:
    TreeBestFiles(const Grammar& g, const Chromosome& best, std::uint32_t maxPrimitives) {
        Geometry geometry;
        DeriveScratch scratch;
        derive(g, best, geometry, scratch, maxPrimitives);
        primitives_ = geometry.primitives.size();
        mesh_ = meshOf(geometry);
    }
    void addJobs(const std::string& folder, std::vector<std::function<void()>>& jobs) const override {
        jobs.push_back([this, folder] { writeModelPicture(mesh_, std::array{View::ThreeQuarter}, PictureSize{}, folder + "/best.png"); });
        jobs.push_back([this, folder] { writePly(mesh_, folder + "/best.ply"); });
        jobs.push_back([this, folder] { writeGlb(mesh_, folder + "/best.glb"); });
        if (mesh_.textures.empty()) jobs.push_back([this, folder] { writeObj(mesh_, folder + "/best.obj"); });
    }
    /// A mesh with textures writes its OBJ once all the others exist, so that its images
    /// (report/texture_files.hpp) never take, nor lose, the name of another output.
    void afterJobs(const std::string& folder) const override {
        if (!mesh_.textures.empty()) writeObj(mesh_, folder + "/best.obj");
    }
    std::size_t size() const override { return primitives_; }

private:
    std::size_t primitives_ = 0;
    Mesh mesh_;
};

class TreeModel final : public LoadedModel {
public:
    TreeModel(const RunSettings& s, Grammar grammar)
        : maxPrimitives_(s.limits.maxPrimitives), grammar_(std::move(grammar)), family_(grammar_) {
        if (grammar_.mandatoryGenes[grammar_.start] > s.limits.maxGenes)
            throw InputError(s.configPath, "[genome] max_genes",
                             std::to_string(s.limits.maxGenes) + " is smaller than the " +
                                 std::to_string(grammar_.mandatoryGenes[grammar_.start]) + " genes every derivation of " +
                                 grammar_.path + " needs");
    }
    const GenomeFamily& family() const override { return family_; }
    const Grammar* tree() const override { return &grammar_; }
    const std::string& source() const override { return grammar_.source; }
    std::vector<std::pair<std::string, std::string>> extraInputs(const std::string& grammarPath) const override {
        const std::filesystem::path dir = std::filesystem::path(grammarPath).parent_path();
        std::vector<std::pair<std::string, std::string>> inputs;
        for (const std::string& f : grammar_.includes) inputs.emplace_back("include", (dir / f).string());
        for (const MeshShape& m : grammar_.meshes) inputs.emplace_back("mesh", (dir / m.path).string());
        for (const Texture& t : grammar_.textures) inputs.emplace_back("texture", t.file);
        return inputs;
    }
    std::span<const std::string_view> modelFormats() const override { return kModelFormats; }
    void writeModel(const Chromosome& c, const std::string& format, const std::string& path, Replace replace) const override {
        Geometry geometry;
        DeriveScratch scratch;
        derive(grammar_, c, geometry, scratch, maxPrimitives_);
        writeModelFile(geometry, format, path, replace);
    }
    std::string describe(const Chromosome& c) const override {
        Geometry geometry;
        DeriveScratch scratch;
        derive(grammar_, c, geometry, scratch, maxPrimitives_);
        return std::to_string(geometry.primitives.size()) + " primitives";
    }
    std::string render(const Chromosome& c, std::span<const View> views, const std::string& viewName, PictureSize size,
                       const std::string& path) const override {
        Geometry geometry;
        DeriveScratch scratch;
        derive(grammar_, c, geometry, scratch, maxPrimitives_);
        const Mesh mesh = meshOf(geometry);
        writeModelPicture(mesh, views, size, path);
        return std::to_string(size.width * int(views.size())) + "x" + std::to_string(size.height) + ", " + viewName + " view" +
               (views.size() > 1 ? "s" : "") + " of " + std::to_string(mesh.triangles.size()) + " triangles";
    }
    std::unique_ptr<BestModelFiles> bestFiles(const Chromosome& best) const override {
        return std::make_unique<TreeBestFiles>(grammar_, best, maxPrimitives_);
    }

private:
    std::uint32_t maxPrimitives_;
    Grammar grammar_;
    TreeFamily family_;
};

}  // namespace

std::unique_ptr<LoadedModel> loadTreeModel(const RunSettings& s, const std::string* text, const std::string& path) {
    return std::make_unique<TreeModel>(s, text ? parseGrammar(*text, path, s.grammarAttrs) : loadGrammar(path, s.grammarAttrs));
}

}  // namespace shapevo
