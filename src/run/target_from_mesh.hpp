// makeTargetFromMesh: what `shapevo target` does. A triangle mesh (any format mesh/mesh_reader.hpp
// reads) becomes a volume target (repaired for a determinable inside, mesh/mesh_repair.hpp, then
// an OpenVDB level set, score/volume/vdb_target_file.hpp) or, given a config whose target kind draws meshes, a picture target
// (the mesh drawn through the config's camera into a PNG its pixel rule reads as hit where the
// mesh is: TargetKind::drawMeshTarget, score/image/image_kind.hpp). Without --voxel-size a volume's
// voxel size is chosen to fit the mesh (fittingVoxelSize) and said on the output. Promises: the
// output name (its extension, that it does not exist) and the image config are checked before the
// mesh is read; nothing is written for a mesh that is refused, and nothing is overwritten.
#pragma once
#include <iosfwd>
#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace shapevo {

/// The options of `shapevo target`, as the command line gives them.
struct TargetRequest {
    std::string meshPath;             ///< the mesh to read
    std::string output;               ///< -o: .vdb, or .png with imageConfig; must not exist
    std::optional<double> voxelSize;  ///< --voxel-size: a volume's voxel edge in model units; none: fittingVoxelSize
    std::string imageConfig;          ///< --image: a config with an image target and camera ("" = a volume)
};

/// Without --voxel-size, the mesh's longest side (of the bounding box of its triangles' corners)
/// is this many voxels.
constexpr int kVoxelsAlongLongestSide = 128;

/// The voxel size `shapevo target` uses without --voxel-size: the longest side of the bounding
/// box of `mesh`'s triangle corners divided by kVoxelsAlongLongestSide, rounded to 3 significant
/// digits (so the printed size, given as --voxel-size, makes the same target). 0 for a mesh
/// without extent.
double fittingVoxelSize(const Mesh& mesh);

/// Writes the target `request` asks for. Prints what was made ("mesh: ...", "voxel size: ..."
/// when it was chosen, "inside: ..." or the pixels covered, "wrote FILE") to `out`, and the mesh
/// reader's warnings ("shapevo: warning: ...") to `err`. @throw InputError for a bad output name, an image config without an image
/// target, or a mesh that cannot be read, repaired or made into the target.
void makeTargetFromMesh(const TargetRequest& request, std::ostream& out, std::ostream& err);

}  // namespace shapevo
