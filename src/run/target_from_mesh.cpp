// `shapevo target`: a mesh made into a volume or a picture target (target_from_mesh.hpp).
#include "run/target_from_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <ostream>
#include <span>
#include <string_view>


#include "base/input_error.hpp"
#include "mesh/corner_box.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_repair.hpp"
#include "run/command_options.hpp"
#include "run/config_file.hpp"
#include "run/model_export.hpp"
#include "score/volume/vdb_target_file.hpp"

namespace shapevo {

namespace {

/// The longest side of the bounding box of `mesh`'s triangle corners.
double longestSide(const Mesh& mesh) {
    if (mesh.triangles.empty()) return 0.0;
    const CornerBox box = cornerBox(mesh);
    return std::max({double(box.hi.x) - box.lo.x, double(box.hi.y) - box.lo.y, double(box.hi.z) - box.lo.z});
}

/// The mesh repaired for a determinable inside, as a level set of the requested voxel size, or
/// of the fitting one (said on `out`).
void writeVolumeTarget(const Mesh& mesh, const TargetRequest& r, std::ostream& out) {
    const MeshRepair repaired = repairForVolume(mesh, r.meshPath);
    out << "mesh: " << describeRepair(repaired) << std::endl;
    double voxelSize = r.voxelSize.value_or(0.0);
    if (!r.voxelSize) {
        voxelSize = fittingVoxelSize(repaired.mesh);
        out << "voxel size: " << voxelSize << " (chosen: the longest side, " << longestSide(repaired.mesh) << " model units, in about "
            << kVoxelsAlongLongestSide << " voxels; --voxel-size sets another)" << std::endl;
    }
    const TargetVdbStats stats = writeTargetVdb(repaired.mesh, voxelSize, r.meshPath, r.output);
    out << "inside: volume " << stats.insideVolume << " (model units^3), " << groupedNumber(stats.insideVoxels) << " voxels of "
        << voxelSize << "\n"
        << "wrote " << r.output << "\n";
}

}  // namespace

double fittingVoxelSize(const Mesh& mesh) {
    const double raw = longestSide(mesh) / kVoxelsAlongLongestSide;
    if (!(raw > 0.0) || !std::isfinite(raw)) return 0.0;
    // 3 significant digits: scale by a power of ten that is exact in a double, round, scale back.
    const int exponent = int(std::floor(std::log10(raw))) - 2;
    const double power = std::pow(10.0, std::abs(exponent));
    return exponent < 0 ? std::round(raw * power) / power : std::round(raw / power) * power;
}

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
