// Image fitness forms; see image_fitness.hpp for the formulas and their sources.
#include "score/image/image_fitness.hpp"

namespace shapevo {

double imageFitness(const FitnessSettings& s, const SilhouetteCounts& c, std::uint64_t hitCount, std::uint32_t genes) {
    if (s.form == FitnessSettings::Form::Smootherstep) {
        const double t = double(hitCount);
        return s.alpha * smootherstep(double(c.hit), 0.0, t) - s.beta * smootherstep(double(c.avoided), 0.0, t) -
               s.gamma * smootherstep(double(genes), s.lengthOptimal, s.lengthMax);
    }
    return s.fillWeight * double(c.hit) + s.avoidWeight * double(c.avoided);
}

}  // namespace shapevo
