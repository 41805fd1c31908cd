// Texture files beside an exported model: an OBJ's material library names its textures'
// images by file name (`map_Kd bricks.png`), so they are copied into the OBJ's folder.
// Promises: an existing file is never replaced. A file of the texture's name that already holds
// the same bytes is used as it is (a model exported again, a texture already in that folder); one
// that holds other bytes is kept and the image gets the next free name "STEM_2.png",
// "STEM_3.png", ... instead. Each copy appears atomically (base/atomic_write.hpp).
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace shapevo {

/// What placeTextures() did: the file name of each of the mesh's textures in `folder`, and the
/// files it created (for removeCreated() when the model cannot be written after all).
struct PlacedTextures {
    std::vector<std::string> names;
    std::vector<std::string> created;
};

/// Copies `mesh.textures` into `folder` (see above).
/// @throw InputError naming the file that cannot be written (those created before it are removed).
PlacedTextures placeTextures(const Mesh& mesh, const std::string& folder);

/// Removes the files placeTextures() created (errors ignored).
void removeCreated(const PlacedTextures& placed);

}  // namespace shapevo
