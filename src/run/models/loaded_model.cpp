// LoadedModel's factory: the family by the grammar file's extension (loaded_model.hpp).
#include "run/models/loaded_model.hpp"

#include "run/models/graph_model.hpp"
#include "run/models/tree_model.hpp"
#include "run/sample_graphs.hpp"

namespace shapevo {

std::unique_ptr<LoadedModel> LoadedModel::load(const RunSettings& s) {
    if (isGraphGrammarPath(s.grammarPath)) return loadGraphModel(s, nullptr, s.grammarPath);
    return loadTreeModel(s, nullptr, s.grammarPath);
}

std::unique_ptr<LoadedModel> LoadedModel::fromText(const RunSettings& s, const std::string& text, const std::string& path) {
    if (isGraphGrammarPath(path)) return loadGraphModel(s, &text, path);
    return loadTreeModel(s, &text, path);
}

}  // namespace shapevo
