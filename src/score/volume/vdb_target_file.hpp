// Volume target files: turning a closed mesh into an OpenVDB level-set file with shapevo's
// metadata, and loading one or more such files into the dense bit grid the scorer uses.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"
#include "score/volume/volume_target.hpp"

namespace shapevo {

/// One target file to load; `avoid` targets mark voxels the model must stay out of.
struct TargetVolumeSpec {
    std::string path;
    bool avoid = false;
};

/// An explicit dense grid box (world units); nx = ceil((max.x - min.x) / voxelSize), etc.
struct GridOverride {
    glm::dvec3 min{0.0}, max{0.0};
    double voxelSize = 0.0;
};

/// What writeTargetVdb made: voxels whose centre the level set puts inside (value <= 0; the
/// voxels loadVolumeTarget sets from this file alone), and their volume in model units^3.
struct TargetVdbStats {
    std::uint64_t insideVoxels = 0;
    double insideVolume = 0.0;
};

/// Converts `mesh` to a narrow-band level set (FloatGrid named "target", grid class level set,
/// 3 voxels half width) and writes it to `outPath` with metadata voxel_size (double),
/// bounds_min / bounds_max (Vec3d, the mesh's world bounds), source (`sourcePath`) and
/// shapevo_role = "fill". The file appears atomically: it is written to a temporary file in the
/// same directory and then renamed (or hard-linked, when not overwriting) into place.
/// @throw InputError if `outPath` exists and `overwrite` is false, if voxelSize is not a
///        positive finite number (or is so small the grid would be absurd), if the mesh has no
///        triangles, if all its triangles lie in one plane (it encloses no volume), if the level
///        set comes out empty or has no voxel centre clearly inside (an open surface whose inside
///        OpenVDB's flood fill cannot find, a surface of zero thickness through voxel centres, or
///        a mesh thinner than a voxel), or if the file cannot be written. Nothing is written when
///        it throws.
TargetVdbStats writeTargetVdb(const Mesh& mesh, double voxelSize, const std::string& sourcePath, const std::string& outPath,
                    bool overwrite = false);

/// Reads each file's first FloatGrid and bakes all of them into one dense VolumeTarget.
/// Dense grid: if `grid` is null, the union of the targets' active-voxel world bounds padded on
/// every side by 25% of its largest extent, with the first target's voxel size and its voxel
/// centres on the first target's voxel centres; otherwise exactly the override box.
/// A dense voxel is inside a target when the target's level set, trilinearly interpolated
/// (openvdb::tools::BoxSampler) at the voxel centre, is <= 0. Inactive values count: level sets
/// from writeTargetVdb hold the negative background deep inside, so the interior is filled.
/// Dense voxels outside a target's active bounding box (plus one voxel) are never inside it.
/// Fill targets set `fill` bits, avoid targets set `avoid` bits; counts and the XXH3-64 hash
/// (grid spec, then fill words, then avoid words, little-endian bytes) are filled in.
/// Of each file the FloatGrid named "target" is used, else the first FloatGrid. Each file is read
/// once, and the hash of its bytes kept (VolumeTarget::fileHashes).
/// @throw InputError naming the path when a file is unreadable, not a VDB, holds no FloatGrid
///        or an empty one; naming "grid override" when the override box is unusable.
VolumeTarget loadVolumeTarget(const std::vector<TargetVolumeSpec>& specs, const GridOverride* grid = nullptr);

}  // namespace shapevo
