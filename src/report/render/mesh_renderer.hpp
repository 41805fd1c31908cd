// MeshRenderer: a software rasterizer that draws a shaded, depth-tested picture of a mesh on the
// CPU (headless; no GPU, no window).
// Promises:
//   - every triangle is drawn from both sides (meshes read from files may wind either way) into
//     a z-buffer of 2 x 2 samples per pixel; the nearest surface at a sample wins whatever the
//     draw order (at equal depth the earlier triangle); a sample is covered when its centre is
//     inside the triangle or on its edge; the 4 samples of a pixel are averaged in linear light
//     (antialiased edges);
//   - flat shading per triangle on its material colour (Mesh::materials; kNeutralColour for a
//     mesh without materials; a textured material shows its colour times the mean colour of its
//     image, image/png_mean_colour.hpp: textures are not mapped pixel by pixel): ambient light plus a key light from the viewer's upper left and a weaker fill
//     from the right, both fixed relative to the camera, so every view is lit; the result is
//     clamped to 1 and encoded as 8-bit sRGB, opaque, on the light kBackground;
//   - triangles with a non-finite projected corner and degenerate ones draw nothing;
//   - deterministic: the same mesh and camera give the same bytes;
//   - buffers are kept between calls and only grow: nothing is allocated per triangle, and a
//     renderer reused for same-sized pictures allocates nothing after the first.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"
#include "report/render/view_camera.hpp"

namespace shapevo {

/// Linear RGB of the background and of a mesh without colours.
inline constexpr glm::vec3 kBackground{0.87f, 0.88f, 0.90f};
inline constexpr glm::vec3 kNeutralColour{0.62f, 0.60f, 0.56f};

class MeshRenderer {
public:
    MeshRenderer();

    /// Draws `mesh` as `camera` sees it into the camera.width x camera.height rectangle whose
    /// top-left pixel is (x0, y0) of an RGBA image `imageWidth` pixels wide (4 bytes per pixel,
    /// rows top to bottom, no padding); the rest of the image is untouched.
    /// @throw std::invalid_argument if the rectangle does not fit in `rgba`, or the mesh's
    ///        triangles or materials index past its vertices or materials.
    void render(const Mesh& mesh, const ViewCamera& camera, std::span<std::uint8_t> rgba, int imageWidth, int x0 = 0,
                int y0 = 0);

    /// Samples per pixel along each axis.
    static constexpr int kSupersample = 2;

private:
    std::vector<std::uint8_t> srgb_;      ///< linear [0, 1] in kSrgbSteps steps -> 8-bit sRGB
    std::vector<float> depth_;            ///< per sample; +inf = nothing drawn
    std::vector<std::uint32_t> surface_;  ///< per sample: the triangle drawn there, or kNone
    std::vector<glm::vec3> shade_;        ///< per triangle: its shaded linear colour
    std::vector<glm::vec3> albedo_;       ///< per material: the colour it is drawn in
    std::vector<glm::vec3> projected_;    ///< per vertex: camera.project() in sample units
};

}  // namespace shapevo
