// The image target kind: a PNG whose pixels say hit / avoid / don't care (score/image/
// image_target.hpp), seen through a camera: a perspective or orthographic silhouette, or a shadow
// on a ground plane (score/image/camera.hpp). Its [target] keys:
//   image = "FILE.png"                                  names this kind
//   cover = "auto" (default) | "dark" | "light" | "opaque"  or  hit_min, hit_max, avoid_min, avoid_max;
//   alpha_threshold
//   fit = "contain" | "cover" | "stretch" | "exact";  scale (contain and stretch only)
//   tolerance (2D graph grammars' drawings: score/image/drawing_scorer.hpp)
// A tree grammar's model is seen as a silhouette or shadow; a 2D graph grammar's drawing from the
// front (score/image/loaded_drawing.hpp).
// and its own section [camera] (projection and its settings). Its IoU is the silhouette IoU
// ("silhouette_iou"), the preset target.cover = "auto" chose is its LoadedTarget::choices(), its
// best-model output best-overlay.png (the silhouette against the picture), its export format png,
// a run hashes the picture, and `shapevo target MESH --image CONFIG` draws a mesh into a picture
// target through a config's camera and pixel rule (an opaque picture, which "auto" reads as dark).
#pragma once
#include <string>

#include "score/image/camera.hpp"
#include "score/image/image_target.hpp"
#include "score/target_kind.hpp"

namespace shapevo {

/// The table entry (score/target_kinds.cpp).
extern const TargetKind imageTargetKind;

class ImageTargetSettings final : public TargetSettings {
public:
    std::string png;  ///< resolved path
    PixelRule rule;
    TargetFit fit = TargetFit::Contain;
    double scale = 1.0;  ///< target.scale: the share of the frame's width and height a fitted picture may take
    int tolerance = 0;   ///< target.tolerance: pixels a drawing's thin lines may be off (graph grammars only)
    CameraSpec camera;

    const TargetKind& kind() const override { return imageTargetKind; }
    bool named() const override { return !image_.empty(); }
    std::vector<std::string> namingKeys() const override { return {"target.image"}; }
    void finish(ConfigReader& config, const std::string& missing) override;
    std::unique_ptr<LoadedTarget> load(const TargetLoadContext& context) const override;
    std::vector<std::string> inputFiles() const override { return {png}; }

    /// The kind's reader (TargetKind::readTarget).
    static std::unique_ptr<TargetSettings> read(SectionReader& target);

private:
    std::string image_;  ///< target.image as written
};

}  // namespace shapevo
