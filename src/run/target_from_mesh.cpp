// `shapevo target`: a mesh made into a volume or a picture target (target_from_mesh.hpp).
#include "run/target_from_mesh.hpp"

#include <array>
#include <optional>
#include <ostream>
#include <span>
#include <string_view>

#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_repair.hpp"
#include "run/command_options.hpp"
#include "run/config_file.hpp"
#include "run/model_export.hpp"
#include "score/volume/vdb_target_file.hpp"

namespace shapevo {

namespace {

/// The mesh repaired for a determinable inside, as a level set of voxelSize voxels.
void writeVolumeTarget(const Mesh& mesh, const TargetRequest& r, std::ostream& out) {
    const MeshRepair repaired = repairForVolume(mesh, r.meshPath);
    out << "mesh: " << describeRepair(repaired) << std::endl;
    const TargetVdbStats stats = writeTargetVdb(repaired.mesh, r.voxelSize, r.meshPath, r.output);
    out << "inside: volume " << stats.insideVolume << " (model units^3), " << groupedNumber(stats.insideVoxels) << " voxels of "
        << r.voxelSize << "\n"
        << "wrote " << r.output << "\n";
}

}  // namespace

void makeTargetFromMesh(const TargetRequest& r, std::ostream& out, std::ostream& err) {
    // --image: a picture through an image config's camera; otherwise a volume.
    constexpr std::array<std::string_view, 1> kImageFormats{"png"};
    requireOutputFormat(r.output, r.imageConfig.empty() ? std::span<const std::string_view>(kTargetFormats) : kImageFormats, "-o");
    refuseExisting(r.output);
    std::optional<RunSettings> imageSettings;
    if (!r.imageConfig.empty()) {
        imageSettings = loadConfig(r.imageConfig, {});
        if (!imageSettings->target->kind().drawMeshTarget)
            throw InputError(r.imageConfig, "", "has no image target and camera ([target] image = \"FILE.png\" and a "
                                                "[camera] section); --image draws through an image config's camera");
    }
    const Mesh mesh = readMesh(r.meshPath);
    for (const std::string& w : mesh.warnings) err << "shapevo: warning: " << w << "\n";
    if (imageSettings) {
        const TargetSettings& through = *imageSettings->target;
        out << through.kind().drawMeshTarget(through, mesh, r.meshPath, r.imageConfig, r.output);
    }
    else writeVolumeTarget(mesh, r, out);
}

}  // namespace shapevo
