// `shapevo target MESH -o FILE`: a volume or picture target made from a mesh (run/target_from_mesh.hpp).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "run/model_export.hpp"
#include "run/target_from_genome.hpp"
#include "run/target_from_mesh.hpp"

namespace shapevo {

namespace {

TargetRequest targetOptions;

}  // namespace

void TargetCommand::addOptions(CLI::App& command) {
    TargetRequest& o = targetOptions;
    command.add_option("mesh", o.meshPath, "triangle mesh, format by extension: .obj, .ply, .stl (read by shapevo) or .off, "
                                           ".gltf, .glb, .fbx, .3mf, .dae, .3ds, .x, .blend, ... (read by Assimp; an unknown "
                                           "extension's error lists them all; a scene's meshes are merged in world space); for "
                                           "a volume its inside must be determinable (holes filled, at most half its surface) and enclose a "
                                           "volume; a mesh without a valid face (all degenerate) or with a face index out of "
                                           "range is refused; or a .genome file of the --image config's grammar, whose model is drawn through its frame (a "
                                           "target the model reaches exactly)")
        ->required();
    command.add_option("-o,--output", o.output, "output .vdb, or .png with --image (must not exist)")->required();
    auto* voxelOpt = command.add_option("--voxel-size", o.voxelSize,
                                        "voxel edge length in model units (default: chosen to fit the mesh, the longest side "
                                        "of its bounding box / " + std::to_string(kVoxelsAlongLongestSide) +
                                            " rounded to 3 significant digits; the chosen size is printed)");
    command.add_option("--image", o.imageConfig, "draw the mesh through the camera of this image config ([target] image and "
                                                 "[camera]) into a PNG of the camera's size that its pixel rule reads as hit "
                                                 "where the mesh is")
        ->excludes(voxelOpt);
}

void TargetCommand::run(const CommandContext&) {
    if (formatOfPath(targetOptions.meshPath) == "genome") return makeTargetFromGenome(targetOptions, std::cout);
    makeTargetFromMesh(targetOptions, std::cout, std::cerr);
}

}  // namespace shapevo
