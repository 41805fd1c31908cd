// Fitness forms: the smootherstep score of ga-shape-grammars.txt eq. 2-6 and the weighted sum
// s_vol of shapegenetics.txt §8, on hand-computed counts.
#include <gtest/gtest.h>

#include <cmath>

#include "score/volume/volume_fitness.hpp"

namespace shapevo {
namespace {

TEST(Smootherstep, IsZeroBelowOneAboveAndPerlinsPolynomialBetween) {
    EXPECT_EQ(smootherstep(-1, 0, 10), 0.0);
    EXPECT_EQ(smootherstep(0, 0, 10), 0.0);
    EXPECT_EQ(smootherstep(10, 0, 10), 1.0);
    EXPECT_EQ(smootherstep(11, 0, 10), 1.0);
    EXPECT_DOUBLE_EQ(smootherstep(5, 0, 10), 0.5);
    const double t = 0.25;
    EXPECT_DOUBLE_EQ(smootherstep(2.5, 0, 10), 6 * std::pow(t, 5) - 15 * std::pow(t, 4) + 10 * std::pow(t, 3));
}

TEST(VolumeFitness, SmootherstepFormCombinesGoodBadAndLength) {
    FitnessSettings s;  // alpha 1, beta 0.8, gamma 0.2, l_opt 40, l_max 100
    VoxelCounts c;
    c.occupied = 600;
    c.inside = 500;   // out = 100
    c.overlap = 50;
    c.outside = 50;   // bad = 100 + 50 + 50 = 200 of 2T = 2000
    const double expected = 1.0 * smootherstep(500, 0, 1000) - 0.8 * smootherstep(200, 0, 2000) - 0.2 * smootherstep(70, 40, 100);
    EXPECT_DOUBLE_EQ(volumeFitness(s, c, 1000, 70), expected);
    // a perfect, short model reaches alpha
    VoxelCounts perfect;
    perfect.occupied = perfect.inside = 1000;
    EXPECT_DOUBLE_EQ(volumeFitness(s, perfect, 1000, 10), 1.0);
}

TEST(VolumeFitness, WeightedSumAddsEveryTermWithItsWeight) {
    FitnessSettings s;
    s.form = FitnessSettings::Form::WeightedSum;
    s.fillWeight = 2;
    s.emptyWeight = -1;
    s.avoidWeight = -10;
    s.overlapWeight = -3;
    s.outsideWeight = -0.5;
    VoxelCounts c;
    c.occupied = 100;
    c.inside = 60;
    c.avoided = 5;  // so 35 voxels are plain empty space
    c.overlap = 4;
    c.outside = 8;
    EXPECT_DOUBLE_EQ(volumeFitness(s, c, 1000, 7), 2 * 60 - 1 * 35 - 10 * 5 - 3 * 4 - 0.5 * 8);
}

TEST(VoxelIoU, CountsOutsideVoxelsInTheUnion) {
    VoxelCounts c;
    c.occupied = 80;
    c.inside = 60;
    c.outside = 20;
    EXPECT_DOUBLE_EQ(voxelIoU(c, 100), 60.0 / (80 + 20 + 100 - 60));
}

}  // namespace
}  // namespace shapevo
