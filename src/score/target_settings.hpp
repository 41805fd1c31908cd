// Target settings: what a config's [target] names, owned by the score stage: the volume files
// (score/vdb_target_file.hpp's TargetVolumeSpec, GridOverride) or one image target.
#pragma once
#include <string>

#include "score/camera.hpp"
#include "score/image_target.hpp"
#include "score/vdb_target_file.hpp"

namespace shapevo {

/// An image target: a PNG whose pixels are classified by `rule` (target.cover or the explicit
/// ranges) and fitted into `camera`'s frame by `fit`.
struct ImageSceneSettings {
    std::string png;
    PixelRule rule;
    TargetFit fit = TargetFit::Contain;
    double scale = 1.0;  ///< target.scale: the share of the frame's width and height a fitted picture may take
    CameraSpec camera;
};

}  // namespace shapevo
