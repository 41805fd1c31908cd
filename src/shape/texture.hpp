// Textures: the images a grammar's `texture NAME "FILE.png" (SX, SY)` statements name, and the
// texture frame each such statement fixes during a derivation (grammars/README.md, "Colours and
// materials"; geometry/texture_uv.hpp turns frames into UV coordinates). A Texture is read and
// checked once when the grammar is loaded; its bytes are what exported models carry, so a file
// changed or removed later does not change what they show. A TextureFrame is plain numbers.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace shapevo {

/// One texture image of a grammar (Grammar::textures).
struct Texture {
    std::string name;               ///< the material name the statement gives (NAME)
    std::string path;               ///< the file as written in the grammar (relative to its folder)
    std::string file;               ///< the file that was read: absolute, normalized
    std::uint16_t material = 0;     ///< index of `name` in Grammar::materialNames
    std::vector<std::uint8_t> png;  ///< the file's bytes (a PNG that image/png_image.hpp reads)
};

/// Where a texture lies in the world: the scope at the `texture` statement (its centre and unit
/// axes; mirrored frames keep their flipped axis) and the world length of one tile of the image
/// along each axis (size / stretch: x = |size.x| / SX, y = |size.y| / SY, z = |size.z| / SX, or
/// the x length where size.z is 0). A length that is not a finite positive number (a zero size
/// or stretch, NaN) means that the texture does not vary along that axis.
struct TextureFrame {
    glm::vec3 origin{0.0f};
    glm::mat3 axes{1.0f};  ///< columns: the frame's x, y, z directions
    glm::vec3 tile{1.0f};
};

}  // namespace shapevo
