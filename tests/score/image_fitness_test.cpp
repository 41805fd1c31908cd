// Image fitness: the smootherstep score of the original code and the weighted sum s_img over
// silhouette counts, and the silhouette IoU, on hand-computed values.
#include <gtest/gtest.h>

#include "score/image/image_fitness.hpp"

namespace shapevo {
namespace {

TEST(ImageFitness, SmootherstepRewardsHitsAndPunishesAvoidedPixelsAndLength) {
    FitnessSettings s;  // the tree/mickey run: good 2, bad 2, length 0.02 over 100..300 genes
    s.alpha = 2.0, s.beta = 2.0, s.gamma = 0.02, s.lengthOptimal = 100, s.lengthMax = 300;
    SilhouetteCounts c;
    c.hit = 500, c.avoided = 250, c.covered = 800;  // T = 1000: step(0.5) = 0.5, step(0.25) = 0.103515625
    EXPECT_DOUBLE_EQ(imageFitness(s, c, 1000, 200), 2.0 * 0.5 - 2.0 * 0.103515625 - 0.02 * 0.5);
    // don't-care pixels (covered, neither hit nor avoid) change nothing
    c.covered = 5000;
    EXPECT_DOUBLE_EQ(imageFitness(s, c, 1000, 200), 2.0 * 0.5 - 2.0 * 0.103515625 - 0.02 * 0.5);
    // both terms saturate at T
    c.hit = 1000, c.avoided = 3000;
    EXPECT_DOUBLE_EQ(imageFitness(s, c, 1000, 50), 2.0 - 2.0);
    EXPECT_DOUBLE_EQ(imageFitness(s, SilhouetteCounts{}, 1000, 50), 0.0);
}

TEST(ImageFitness, WeightedSumCountsHitAndAvoidPixelsOnly) {
    FitnessSettings s;
    s.form = FitnessSettings::Form::WeightedSum;
    s.fillWeight = 1.5, s.avoidWeight = -10.0, s.emptyWeight = -100.0, s.overlapWeight = -100.0;
    SilhouetteCounts c;
    c.hit = 100, c.avoided = 3, c.covered = 400;
    EXPECT_DOUBLE_EQ(imageFitness(s, c, 1000, 7), 150.0 - 30.0);
}

TEST(ImageFitness, IoUIsHitOverUnion) {
    SilhouetteCounts c;
    c.hit = 50, c.covered = 80;
    EXPECT_DOUBLE_EQ(silhouetteIoU(c, 100), 50.0 / 130.0);
    c.hit = 100, c.covered = 100;
    EXPECT_DOUBLE_EQ(silhouetteIoU(c, 100), 1.0);
    EXPECT_DOUBLE_EQ(silhouetteIoU(SilhouetteCounts{}, 0), 0.0);
}

}  // namespace
}  // namespace shapevo
