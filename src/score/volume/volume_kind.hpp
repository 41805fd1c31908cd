// The volume target kind: one or more OpenVDB level sets (fill and avoid) baked into the dense bit
// rows the volume scorer counts (score/volume/vdb_target_file.hpp). Its [target] keys:
//   fill = "FILE.vdb" | ["A.vdb", ...]   the model should fill these (at least one)
//   avoid = ...                          the model must stay out of these
//   grid_min, grid_max, voxel_size       the dense grid, all three or none (default: from the fills)
// Its IoU is the voxel IoU ("voxel_iou"), its best-model output best.vdb (the model's voxels), its
// export format vdb, and a run hashes every fill and avoid file.
#pragma once
#include <optional>
#include <vector>

#include "score/target_kind.hpp"
#include "score/volume/vdb_target_file.hpp"

namespace shapevo {

/// The table entry (score/target_kinds.cpp).
extern const TargetKind volumeTargetKind;

class VolumeTargetSettings final : public TargetSettings {
public:
    std::vector<TargetVolumeSpec> targets;  ///< fills first, then avoids; paths resolved
    std::optional<GridOverride> grid;

    const TargetKind& kind() const override { return volumeTargetKind; }
    bool named() const override;
    std::vector<std::string> namingKeys() const override;
    void finish(ConfigReader& config, const std::string& missing) override;
    std::unique_ptr<LoadedTarget> load(const TargetLoadContext& context) const override;
    std::vector<std::string> inputFiles() const override;

    /// The kind's reader (TargetKind::readTarget).
    static std::unique_ptr<TargetSettings> read(SectionReader& target);

private:
    GridOverride gridKeys_;  ///< grid_min, grid_max, voxel_size as read
    bool hasMin_ = false, hasMax_ = false, hasVoxelSize_ = false;
};

}  // namespace shapevo
