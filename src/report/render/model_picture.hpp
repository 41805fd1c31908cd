// Model pictures: one or more views of a mesh side by side in one PNG (what a run's best.png and
// `shapevo render` write). Each view is `size`; the picture is (views x width) x height, views
// left to right in the order given, each framed on its own (view_camera.hpp) and drawn by
// MeshRenderer (mesh_renderer.hpp). The same mesh, views and size give the same bytes.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "report/render/mesh_renderer.hpp"
#include "report/render/view_camera.hpp"

namespace shapevo {

struct PictureSize {
    int width = 800, height = 600;
};

/// The largest picture side and the most pixels one picture (a whole contact sheet too) may have.
inline constexpr int kMaxPictureSide = 8192;
inline constexpr long long kMaxPicturePixels = 4096LL * 4096LL;

/// A --size option: "WxH" (e.g. 800x600; also 'X'), whole numbers from 16 to kMaxPictureSide.
/// @throw InputError(option) saying what was expected.
PictureSize parsePictureSize(const std::string& text, const std::string& option = "--size");

/// The RGBA pixels (rows top to bottom) of `views` of `mesh`, each `size`, side by side.
/// @throw InputError("--size") if the whole picture has more than kMaxPicturePixels pixels.
std::vector<std::uint8_t> renderViews(const Mesh& mesh, std::span<const View> views, PictureSize size,
                                      MeshRenderer& renderer);

/// renderViews() written to `path` as a PNG, atomically (image/png_writer.hpp).
/// @throw InputError naming `path` if it cannot be written.
void writeModelPicture(const Mesh& mesh, std::span<const View> views, PictureSize size, const std::string& path);

}  // namespace shapevo
