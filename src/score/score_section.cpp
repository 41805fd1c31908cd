// The [score] section's reader.
#include "score/score_section.hpp"

#include "base/input_error.hpp"

namespace shapevo {

void readScoreSection(SectionReader& r, FitnessSettings& f, IncrementalSettings& incremental) {
    std::string form = "smootherstep";
    r.string("form", form);
    if (form == "smootherstep") f.form = FitnessSettings::Form::Smootherstep;
    else if (form == "weighted") f.form = FitnessSettings::Form::WeightedSum;
    else r.fail("form", "score.form must be \"smootherstep\" or \"weighted\", got \"" + shortened(form) + "\"");
    constexpr double big = 1e12;
    r.number("alpha", f.alpha, -big, big);
    r.number("beta", f.beta, -big, big);
    r.number("gamma", f.gamma, -big, big);
    r.number("length_optimal", f.lengthOptimal, 0, big);
    r.number("length_max", f.lengthMax, 0, big);
    r.number("fill_weight", f.fillWeight, -big, big);
    r.number("empty_weight", f.emptyWeight, -big, big);
    r.number("avoid_weight", f.avoidWeight, -big, big);
    r.number("overlap_weight", f.overlapWeight, -big, big);
    r.number("outside_weight", f.outsideWeight, -big, big);
    r.flag("incremental", incremental.enabled);
    r.number("cache_mb", incremental.cacheMb, 1, 1 << 20);
    r.flag("check_incremental", incremental.check);
    if (f.lengthMax <= f.lengthOptimal)
        r.failKeys({"score.length_optimal", "score.length_max"}, "[score]", "length_max must be greater than length_optimal");
}

}  // namespace shapevo
