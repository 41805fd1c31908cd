// The derivation-tree family's LoadedModel (.grammar, .rule, .pcg): its grammar through the front ends
// (grammar/front_ends.hpp), its genome TreeFamily, its models written as meshes.
#pragma once
#include <memory>
#include <string>

#include "run/models/loaded_model.hpp"

namespace shapevo {

/// From `text` (null: read `path`). @throw InputError for a bad grammar, or one whose every
/// derivation needs more genes than genome.max_genes.
std::unique_ptr<LoadedModel> loadTreeModel(const RunSettings& s, const std::string* text, const std::string& path);

}  // namespace shapevo
