// Model volume: a model's voxels as an OpenVDB file, exactly the voxels the volume scorer counts
// (the scorer's own Voxelizer on the target's grid), for viewing next to the target in Blender,
// Houdini or any VDB viewer.
#pragma once
#include <string>

#include "shape/primitive.hpp"
#include "score/volume/volume_target.hpp"

namespace shapevo {

/// Voxelizes `geometry` on `grid` and writes one FloatGrid named "density": a fog volume with
/// value 1 at every covered voxel (active) and background 0. Index (i, j, k) is dense voxel
/// (i, j, k), its centre at grid.origin + (i + 0.5, j + 0.5, k + 0.5) * voxelSize in world space,
/// so the file lines up with the target. Metadata: source = "shapevo model", shapevo_role =
/// "model", voxel_size (double), primitives (int64). Voxels outside the grid are not written.
/// The file appears atomically (temporary file, then rename), replacing an older one.
/// @throw InputError naming `path` if the grid is empty or the file cannot be written.
void writeModelVdb(const Geometry& geometry, const GridSpec& grid, const std::string& path);

}  // namespace shapevo
