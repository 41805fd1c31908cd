// Target settings: what a config's [target] names, owned by the score stage: the volume files
// (score/vdb_target_file.hpp's TargetVolumeSpec, GridOverride) or one image target.
#pragma once
#include <string>

#include "score/camera.hpp"
#include "score/image_target.hpp"
#include "score/vdb_target_file.hpp"

namespace shapevo {

/// An image target: a PNG whose pixels are classified by `rule`, seen through `camera`.
struct ImageSceneSettings {
    std::string png;
    PixelRule rule;
    CameraSpec camera;
};

}  // namespace shapevo
