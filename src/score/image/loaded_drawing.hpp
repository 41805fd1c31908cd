// The image target kind's loaded target for the graph-derivation family (2D graph grammars): the
// picture is matched by the model's drawing (score/image/drawing_scorer.hpp), seen from the front
// through [camera] with projection = "orthographic": the eye on the z axis side of look_at
// (looking along -z), up = +y, view_height model units across the picture's height, look_at's x and
// y the picture's centre. target.tolerance (pixels) forgives thin lines drawn next to the
// target's. Its outputs are the image kind's: the silhouette IoU (the drawing's exact IoU),
// best-overlay.png and export png (the drawing's pixels over the picture).
#pragma once
#include <memory>

#include "genome/families/graph_family.hpp"
#include "graph/drawing_raster.hpp"
#include "score/image/camera.hpp"
#include "score/image/image_kind.hpp"

namespace shapevo {

/// The raster frame a front orthographic camera shows. @throw InputError(file, "[camera]") for
/// another projection or direction.
graph::RasterFrame drawingFrame(const CameraSpec& camera, const std::string& file);

std::unique_ptr<LoadedTarget> loadDrawingTarget(const ImageTargetSettings& s, const TargetLoadContext& c, const GraphFamily& family);

}  // namespace shapevo
