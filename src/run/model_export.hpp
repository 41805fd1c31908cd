// Model export: the files `shapevo sample` and `shapevo export` write. A model is written as a
// mesh (obj, ply, glb); `export` also writes what only the run's target kind can make (its
// TargetKind::exportFormats: vdb, the model's voxels on a volume target's grid; png, its
// silhouette over an image target), loading the scene from the config and grammar stored in the
// checkpoint, exactly as `resume` does.
// Every command checks its output file's extension before it reads or writes anything.
#pragma once
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/atomic_write.hpp"
#include "genome/chromosome.hpp"
#include "shape/primitive.hpp"
#include "grammar/grammar.hpp"
#include "run/models/loaded_model.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// A file's format from its extension, lower-cased ("out/m.OBJ" -> "obj"; "" without one).
std::string formatOfPath(const std::string& path);

/// What `shapevo sample -o` writes (a mesh), what `shapevo target` writes.
inline constexpr std::array<std::string_view, 3> kModelFormats{"obj", "ply", "glb"};
/// What a 2D graph grammar's model is written as (run/models/graph_model.hpp).
inline constexpr std::array<std::string_view, 2> kDrawingFormats{"svg", "png"};
inline constexpr std::array<std::string_view, 1> kTargetFormats{"vdb"};
/// What `shapevo export` writes: the mesh formats, every target kind's export formats
/// (score/target_kinds.hpp), then the drawing formats, each once: obj, ply, glb, vdb, png, svg.
std::vector<std::string_view> exportFormats();
/// "obj, ply, glb or png": formats for a message.
std::string formatList(std::span<const std::string_view> formats);
/// What `shapevo sample --genome` writes.
inline constexpr std::array<std::string_view, 1> kGenomeFormats{"genome"};

/// The format of output file `path` (its extension), which must be one of `accepted`; `option`
/// names the command's flag in the message ("-o"). A `requested` format (export's --format; ""
/// = none) must agree with the extension. @throw InputError(path) for a path without an
/// extension, with another one, or with one that is not the requested format.
std::string requireOutputFormat(const std::string& path, std::span<const std::string_view> accepted,
                                const std::string& option, const std::string& requested = "");

/// Write `geometry` as a mesh in `format` (obj, ply or glb) with its colours and materials, if
/// any (report/model_writer.hpp, mesh/glb_writer.hpp; an OBJ with materials also writes the MTL
/// mtlPathFor(path)). With Replace::Never, what `sample` and `export` use, no existing file
/// (the OBJ's MTL included) is replaced. @throw InputError(path) for another format.
void writeModelFile(const Geometry& geometry, const std::string& format, const std::string& path,
                    Replace replace = Replace::Always);

/// The best individual of a checkpoint over all islands, with the model family (its grammar, as
/// stored in the checkpoint) and the settings it needs (the grammar owns the meshes its geometry
/// points to).
struct CheckpointBest {
    RunSettings settings;
    std::unique_ptr<LoadedModel> model;
    Chromosome best;
    std::string from;  ///< "island R, fitness F"
};

/// Read a complete checkpoint folder (see checkpoint/checkpoint_path.hpp for turning what a user
/// names into one). @throw InputError if it is incomplete or a file is invalid.
CheckpointBest bestOfCheckpoint(const std::string& folder);

/// Write `b.best` to `path` in `format` (empty: the path's extension): obj, ply, glb (never
/// replacing an existing file, the OBJ's MTL included), or a target kind's format (vdb, png)
/// through the run's scene. Returns what was written, e.g. "wrote m.obj (12 primitives; island 0,
/// fitness 0.91)". @throw InputError for an unknown format or one that does not fit the target.
std::string exportCheckpointBest(const CheckpointBest& b, std::string format, const std::string& path);

}  // namespace shapevo
