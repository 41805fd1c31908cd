// ImageScorer: the model masks for overlays (the hot path lives in the header).
#include "score/image_scorer.hpp"

namespace shapevo {

void ImageScorer::modelMask(const Chromosome& c, Workspace& w, std::vector<std::uint8_t>& mask) const {
    derive(grammar_, c, w.geometry, w.derive, maxPrimitives());  // a non-finite primitive is left out
    w.raster.clear();
    w.raster.add(w.geometry);
    w.raster.fillMask(mask);
    w.raster.clear();
}

void silhouetteMask(const Geometry& geometry, const Camera& camera, std::vector<std::uint8_t>& mask) {
    SilhouetteRaster raster(camera);
    raster.add(geometry);
    raster.fillMask(mask);
}

}  // namespace shapevo
