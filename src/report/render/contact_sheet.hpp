// ContactSheet: many models in one PNG, a grid of tiles (what `shapevo sample --count N -o
// sheet.png` writes). Promises: N tiles of `tile` pixels each, ceil(sqrt(N)) columns, as many rows
// as needed, in reading order, kGutter pixels of kGutterColour between tiles and round the sheet;
// each tile is a three-quarter view (view_camera.hpp) framed on its own model, with an optional
// label in its bottom-left corner in the built-in small font (image/rgba_canvas.hpp: digits,
// '.', '-', '+', 'e'; other characters are left blank), e.g. the model's seed. Tiles not drawn
// stay background. The same models give the same bytes.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/rgba.hpp"
#include "mesh/mesh.hpp"
#include "report/render/mesh_renderer.hpp"
#include "report/render/model_picture.hpp"

namespace shapevo {

class ContactSheet {
public:
    static constexpr int kGutter = 4;
    static constexpr Rgba kGutterColour{196, 199, 204, 255};

    /// An empty sheet for `count` (>= 1) tiles of `tile` size.
    /// @throw InputError("--count") if the sheet would have more than kMaxPicturePixels pixels.
    ContactSheet(int count, PictureSize tile);

    int width() const { return width_; }
    int height() const { return height_; }
    int columns() const { return columns_; }
    /// The top-left pixel of tile `index` (0-based, reading order).
    int tileX(int index) const;
    int tileY(int index) const;

    /// Draws `mesh` into tile `index` (0 <= index < count) with `label` (may be empty).
    void draw(int index, const Mesh& mesh, const std::string& label);

    const std::vector<std::uint8_t>& pixels() const { return rgba_; }  ///< RGBA, rows top to bottom
    /// Writes the sheet as a PNG, atomically. @throw InputError naming `path` if it cannot.
    void write(const std::string& path) const;

private:
    int count_, columns_, rows_, width_, height_;
    PictureSize tile_;
    std::vector<std::uint8_t> rgba_;
    MeshRenderer renderer_;
};

}  // namespace shapevo
