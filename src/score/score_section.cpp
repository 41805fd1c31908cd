// The [score] section's reader.
#include "score/score_section.hpp"

#include "base/input_error.hpp"

namespace shapevo {

void readScoreSection(SectionReader& r, FitnessSettings& f, IncrementalSettings& incremental) {
    std::string form = "smootherstep";
    r.string("form", form,
             "the fitness: \"smootherstep\" (good, bad and length in smootherstep curves) or \"weighted\" (a weighted "
             "sum of counts)");
    if (form == "smootherstep") f.form = FitnessSettings::Form::Smootherstep;
    else if (form == "weighted") f.form = FitnessSettings::Form::WeightedSum;
    else r.fail("form", "score.form must be \"smootherstep\" or \"weighted\", got \"" + shortened(form) + "\"");
    constexpr double big = 1e12;
    r.number("alpha", f.alpha, -big, big, "smootherstep form: weight of the good (target voxels or pixels covered)");
    r.number("beta", f.beta, -big, big,
             "smootherstep form: weight of the bad (covered where the target is not, or avoided)");
    r.number("gamma", f.gamma, -big, big, "smootherstep form: weight of the length penalty");
    r.number("length_optimal", f.lengthOptimal, 0, big, "the length penalty is 0 up to this many genes");
    r.number("length_max", f.lengthMax, 0, big,
             "the length penalty reaches 1 at this many genes; must be greater than length_optimal");
    r.number("fill_weight", f.fillWeight, -big, big, "weighted form: per target voxel or pixel covered");
    r.number("empty_weight", f.emptyWeight, -big, big, "weighted form: per target voxel or pixel left empty");
    r.number("avoid_weight", f.avoidWeight, -big, big, "weighted form: per avoided voxel or pixel covered");
    r.number("overlap_weight", f.overlapWeight, -big, big,
             "weighted form: per voxel covered by more than one primitive");
    r.number("outside_weight", f.outsideWeight, -big, big,
             "weighted form: per voxel or pixel covered outside the target");
    r.flag("incremental", incremental.enabled,
           "score a child from its parent's counts where its operator changed one subtree, and reuse the fitness of a "
           "chromosome already scored; false scores every model the full way. Results are bit-identical either way");
    r.number("cache_mb", incremental.cacheMb, 1, 1 << 20,
             "the most memory incremental scoring's caches may take per evaluation thread, and what an island's "
             "models may keep for scoring their children, in MiB each");
    r.flag("check_incremental", incremental.check,
           "also score every model the full way and stop (exit 1) at the first difference");
    if (f.lengthMax <= f.lengthOptimal)
        r.failKeys({"score.length_optimal", "score.length_max"}, "[score]",
                   "length_max must be greater than length_optimal");
}

}  // namespace shapevo
