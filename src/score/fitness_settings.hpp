// FitnessSettings: the [score] keys of the fitness forms, the same for every target kind (the
// volume forms, score/volume/volume_fitness.hpp; the image forms, score/image/image_fitness.hpp):
//   form = "smootherstep" (default) | "weighted"
//   smootherstep: alpha, beta, gamma, length_optimal, length_max
//   weighted sum: fill_weight, empty_weight, avoid_weight, overlap_weight, outside_weight
// score/score_section.hpp reads them.
#pragma once

namespace shapevo {

/// step(x, lo, hi): 0 below lo, 1 above hi, Perlin's smootherstep 6t^5 - 15t^4 + 10t^3 between.
inline double smootherstep(double x, double lo, double hi) {
    if (x <= lo) return 0.0;
    if (x >= hi) return 1.0;
    const double t = (x - lo) / (hi - lo);
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

struct FitnessSettings {
    enum class Form { Smootherstep, WeightedSum } form = Form::Smootherstep;
    // smootherstep form
    double alpha = 1.0, beta = 0.8, gamma = 0.2;
    double lengthOptimal = 40, lengthMax = 100;
    // weighted-sum form
    double fillWeight = 1.0, emptyWeight = -1.0, avoidWeight = -10.0, overlapWeight = -1.0, outsideWeight = -1.0;
};

}  // namespace shapevo
