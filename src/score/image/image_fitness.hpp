// Image fitness: the scores of the papers over silhouette pixel counts.
//  - smootherstep (the original code's image score, ga-shape-grammars.txt eq. 2-6):
//      f = alpha*step(hit, 0, T) - beta*step(avoided, 0, T) - gamma*step(genes, l_opt, l_max)
//    where hit = covered hit pixels ("good"), avoided = covered avoid pixels ("bad"), T = the
//    target's hit pixels. On a black-on-white target with the default PixelRule, avoid pixels
//    are exactly the non-target pixels, so "bad" is model AND NOT target as in their code.
//  - weighted sum s_img (shapegenetics.txt §8: the sum over pixels of the target's weight where
//    the model is): fillWeight*hit + avoidWeight*avoided; don't-care pixels weigh nothing.
// Both read FitnessSettings (alpha = good weight, beta = bad weight, gamma = length weight,
// lengthOptimal / lengthMax; fillWeight, avoidWeight); the volume-only weights are unused.
#pragma once
#include <cstdint>

#include "score/image/silhouette_raster.hpp"
#include "score/fitness_settings.hpp"

namespace shapevo {

double imageFitness(const FitnessSettings& s, const SilhouetteCounts& c, std::uint64_t hitCount, std::uint32_t genes);

/// Intersection over union of the model's pixels and the target's hit pixels.
inline double silhouetteIoU(const SilhouetteCounts& c, std::uint64_t hitCount) {
    const double uni = double(hitCount + c.covered - c.hit);
    return uni > 0 ? double(c.hit) / uni : 0.0;
}

}  // namespace shapevo
