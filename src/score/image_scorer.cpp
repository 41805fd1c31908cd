// ImageScorer: incremental drawing and its check, and the model masks for overlays (the rest of
// the hot path lives in the header).
#include "score/image_scorer.hpp"

#include <string>

namespace shapevo {

void ImageScorer::drawCached(Workspace& w) const {
    drawThroughCache(
        *w.cache, w.geometry.primitives, w.probes, w.words,
        [](const Primitive&) { return false; },  // every kind's silhouette is worth keeping
        [&](const PrimitiveCache<WordMask>::Found& found) { w.raster.replay(found.records, found.extra); },
        [&](const Primitive& p, std::vector<WordMask>& words) -> std::uint64_t {
            w.spans.clear();
            w.raster.addRecorded(p, w.geometry.meshes, w.spans);
            w.raster.wordMasks(w.spans, words);
            return SilhouetteRaster::boundsOf(w.spans);  // kept beside the words: replay needs no per-word bookkeeping
        });
    if (w.cache->full()) noteCacheFull();
}

void ImageScorer::checkAgainstFull(Workspace& w, const SilhouetteCounts& counts) const {
    w.raster.add(w.geometry);
    const SilhouetteCounts full = w.raster.score(target_);
    if (full.covered != counts.covered || full.hit != counts.hit || full.avoided != counts.avoided)
        throw IncrementalMismatch("incremental image scoring differs from the full one: covered/hit/avoided " +
                                  std::to_string(counts.covered) + "/" + std::to_string(counts.hit) + "/" +
                                  std::to_string(counts.avoided) + " against " + std::to_string(full.covered) + "/" +
                                  std::to_string(full.hit) + "/" + std::to_string(full.avoided) + " (" +
                                  std::to_string(w.geometry.primitives.size()) + " primitives)");
}

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
