// Image targets from meshes: a mesh's silhouette (perspective or orthographic camera) or shadow
// (shadow camera) drawn through a config's camera into a PNG that the config's pixel rule reads
// as hit where the mesh is and avoid (or don't care) elsewhere, so a model can be aimed at
// another model's picture. The drawing is the image scorer's own: a pixel is covered exactly
// when its centre lies in a projected triangle (score/image/silhouette_raster.hpp), with the same
// near-plane and ground cut; the mesh need not be closed.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "score/image/camera.hpp"
#include "score/image/image_target.hpp"

namespace shapevo {

/// The mesh's picture through `camera`, one byte per pixel (rows from the top): 1 = covered.
/// Triangles with an index out of range are skipped.
std::vector<std::uint8_t> meshSilhouette(const Mesh& mesh, const Camera& camera);

/// The two grey levels a black-on-white picture uses so that `rule` reads them as hit and as
/// avoid: 0 and 255 under the default rule; otherwise a level in each range (the background a
/// level that is not hit when the rule has no avoid range). `ok` is false when no level is hit.
struct PictureLevels {
    std::uint8_t hit = 0, background = 255;
    bool ok = true;
};
PictureLevels pictureLevels(const PixelRule& rule);

/// Draws `mesh` through `camera` and writes it to `outPath` (opaque grey PNG of the camera's
/// size, atomically, never replacing a file). Returns the number of covered pixels.
/// @throw InputError naming `meshPath` when the mesh covers no pixel centre (it is out of view),
///        naming `rulePlace` when `rule` has no hit level, naming `outPath` when it exists or
///        cannot be written.
std::uint64_t writeMeshImageTarget(const Mesh& mesh, const Camera& camera, const PixelRule& rule,
                                   const std::string& meshPath, const std::string& rulePlace,
                                   const std::string& outPath);

}  // namespace shapevo
