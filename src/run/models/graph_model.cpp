// The graph-derivation family's LoadedModel (graph_model.hpp).
#include "run/models/graph_model.hpp"

#include <array>
#include <filesystem>

#include "base/input_error.hpp"
#include "graph/read_graph_grammar.hpp"
#include "graph/svg_writer.hpp"
#include "report/graph_picture.hpp"
#include "run/model_export.hpp"
#include "run/sample_graphs.hpp"

namespace shapevo {

namespace {

graph::DeriveLimits limitsFor(const RunSettings& s, const graph::GraphGrammar& g) {
    graph::DeriveLimits limits = s.graphLimits;
    if (limits.maxSteps == 0 && g.globalLimit == 0) limits.maxSteps = kDefaultGraphSampleSteps;
    return limits;
}

/// `drawing` as `format` (svg or png) at `path`.
void writeDrawing(const graph::Drawing& drawing, const graph::GraphGrammar& g, const std::string& format, const std::string& path,
                  Replace replace) {
    const graph::DrawingCanvas canvas = graph::canvasOf(drawing, kGraphModelMargin);
    if (format == "svg") {
        const std::string svg = graph::drawingSvg(drawing, g.filters, canvas);
        writeStreamAtomically(path, [&](std::ostream& o) { o << svg; }, replace);
    } else if (format == "png") {
        if (replace == Replace::Never && std::filesystem::exists(path))
            throw InputError(path, "", "already exists; refusing to overwrite it");
        writeDrawingPng(drawing, canvas, naturalPictureSize(canvas), path);
    } else {
        throw InputError(path, "", "unknown drawing format '" + format + "' (expected svg or png)");
    }
}

/// best.svg and best.png of one derived drawing.
class GraphBestFiles final : public BestModelFiles {
public:
    GraphBestFiles(const GraphFamily& family, const Chromosome& best) : grammar_(family.grammar()) {
        try {
            drawing_ = family.drawing(best);
        } catch (const InputError&) {
            // a best whose derivation fails (every model failed): no drawing, an empty picture
        }
    }
    void addJobs(const std::string& folder, std::vector<std::function<void()>>& jobs) const override {
        jobs.push_back([this, folder] { writeDrawing(drawing_, grammar_, "svg", folder + "/best.svg", Replace::Always); });
        jobs.push_back([this, folder] { writeDrawing(drawing_, grammar_, "png", folder + "/best.png", Replace::Always); });
    }
    std::size_t size() const override { return drawing_.shapes.size(); }

private:
    const graph::GraphGrammar& grammar_;
    graph::Drawing drawing_;
};

class GraphModel final : public LoadedModel {
public:
    GraphModel(const RunSettings& s, graph::GraphGrammar grammar)
        : grammar_(std::move(grammar)), family_(grammar_, limitsFor(s, grammar_)) {}
    const GenomeFamily& family() const override { return family_; }
    const GraphFamily* graph() const override { return &family_; }
    const std::string& source() const override { return grammar_.source; }
    std::vector<std::pair<std::string, std::string>> extraInputs(const std::string&) const override { return {}; }
    std::span<const std::string_view> modelFormats() const override { return kDrawingFormats; }
    void writeModel(const Chromosome& c, const std::string& format, const std::string& path, Replace replace) const override {
        writeDrawing(family_.drawing(c), grammar_, format, path, replace);
    }
    std::string describe(const Chromosome& c) const override {
        const graph::DeriveResult r = family_.derive(c);
        return std::to_string(family_.drawing(r.graph).shapes.size()) + " shapes, " +
               std::to_string(r.steps) + " steps";
    }
    std::string render(const Chromosome& c, std::span<const View>, const std::string&, PictureSize size,
                       const std::string& path) const override {
        const graph::Drawing drawing = family_.drawing(c);
        writeDrawingPng(drawing, graph::canvasOf(drawing, kGraphModelMargin), size, path);
        return std::to_string(size.width) + "x" + std::to_string(size.height) + " drawing of " + std::to_string(drawing.shapes.size()) +
               " shapes";
    }
    std::unique_ptr<BestModelFiles> bestFiles(const Chromosome& best) const override {
        return std::make_unique<GraphBestFiles>(family_, best);
    }

private:
    graph::GraphGrammar grammar_;
    GraphFamily family_;
};

}  // namespace

std::unique_ptr<LoadedModel> loadGraphModel(const RunSettings& s, const std::string* text, const std::string& path) {
    return std::make_unique<GraphModel>(s, text ? graph::parseGraphGrammar(*text, path) : graph::readGraphGrammar(path));
}

}  // namespace shapevo
