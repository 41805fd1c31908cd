// Graph pictures: a graph grammar's Drawing (graph/drawing.hpp) painted with cairo as an SVG
// renderer paints the SVG that graph/svg_writer.hpp writes — the canvas fitted into the picture
// (preserveAspectRatio xMidYMid meet) on white; circles, lines, rects and paths (M L H V Q T C S Z)
// with SVG's defaults (fill black, no stroke, stroke-width 1, butt caps, miter joins with limit 4)
// and the attributes fill, stroke, stroke-width, fill-opacity, stroke-opacity, opacity,
// stroke-linecap, stroke-linejoin, stroke-miterlimit, stroke-dasharray, fill-rule, display and
// visibility; lengths at 96 dpi. Not painted: filters, transforms other than an image's
// rotation, inline style. An image is not loaded: its rotated rectangle is filled light grey and
// outlined (a placeholder). The same drawing and size give the same pixels.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "graph/drawing.hpp"
#include "report/render/model_picture.hpp"

namespace shapevo {

/// The picture size at the SVG's own scale (one pixel per user unit, as a browser at 100 %
/// shows it), rounded up, at least 16 pixels a side and scaled down to fit kMaxPictureSide and
/// kMaxPicturePixels.
PictureSize naturalPictureSize(const graph::DrawingCanvas& canvas);

/// The RGBA pixels (rows top to bottom, opaque) of `drawing` seen through `canvas`, `size` big.
std::vector<std::uint8_t> paintDrawing(const graph::Drawing& drawing, const graph::DrawingCanvas& canvas, PictureSize size);

/// paintDrawing() as a PNG at `path`, atomically. @throw InputError naming `path`.
void writeDrawingPng(const graph::Drawing& drawing, const graph::DrawingCanvas& canvas, PictureSize size,
                     const std::string& path);

}  // namespace shapevo
