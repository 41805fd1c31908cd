// The sync meeting's record: combining the records of several islands gives, row by row, what a
// per-generation reduction gives (sums, the largest best with its island's IoU, the larger IoU
// among equal bests), whatever order the islands combine in; decisions are any-rank maxima.
#include <gtest/gtest.h>

#include <cmath>

#include "island/island_meeting.hpp"

namespace shapevo {
namespace {

MeetingInput island(double bestA, double iouA, double bestB, double iouB, std::vector<double> fitness, int signal) {
    MeetingInput in;
    GenerationStats a, b;
    a.generation = 7, a.best = bestA, a.iou = iouA, a.evaluations = 100, a.seconds = 1.5;
    b.generation = 8, b.best = bestB, b.iou = iouB, b.evaluations = 200, b.seconds = 2.5;
    in.rows = {islandRow(a, fitness), islandRow(b, fitness)};
    in.signal = signal;
    in.waitShare = 0.01 * (signal + 1);
    return in;
}

MeetingResult combined(const std::vector<MeetingInput>& islands, const std::vector<int>& order) {
    std::vector<double> acc = encodeMeeting(islands[std::size_t(order[0])]);
    for (std::size_t k = 1; k < order.size(); ++k) {
        const std::vector<double> other = encodeMeeting(islands[std::size_t(order[k])]);
        combineMeetings(other.data(), acc.data());
    }
    return decodeMeeting(acc, islands[0], int(islands.size()));
}

TEST(IslandMeeting, RowsAreTheSumsAndTheLargestBestWithItsIslandsIoUInAnyOrder) {
    const std::vector<MeetingInput> islands{island(0.5, 0.30, 0.9, 0.70, {0.5, 0.1}, 0),
                                            island(0.8, 0.60, 0.9, NAN, {0.8, 0.2, 0.2}, 15),
                                            island(0.7, 0.99, 0.4, 0.95, {0.7}, 0)};
    for (const std::vector<int>& order : {std::vector<int>{0, 1, 2}, {2, 1, 0}, {1, 2, 0}}) {
        const MeetingResult m = combined(islands, order);
        ASSERT_EQ(m.rows.size(), 2u);
        EXPECT_EQ(m.rows[0].generation, 7u);
        EXPECT_EQ(m.rows[0].best, 0.8);
        EXPECT_EQ(m.rows[0].iou, 0.60);  // the IoU of island 1, which holds the best, not the largest IoU
        EXPECT_EQ(m.rows[1].best, 0.9);
        EXPECT_EQ(m.rows[1].iou, 0.70);  // equal bests: the larger IoU; a NaN IoU never wins
        EXPECT_EQ(m.rows[0].evaluations, 300u);
        const double mean = (0.5 + 0.1 + 0.8 + 0.2 + 0.2 + 0.7) / 6;
        EXPECT_NEAR(m.rows[0].mean, mean, 1e-15);
        const double squares = (0.25 + 0.01 + 0.64 + 0.04 + 0.04 + 0.49) / 6;
        EXPECT_NEAR(m.rows[1].std, std::sqrt(squares - mean * mean), 1e-12);
        EXPECT_EQ(m.signal, 15);
        EXPECT_NEAR(m.waitShareMax, 0.16, 1e-15);
        EXPECT_NEAR(m.waitShareMean, (0.01 + 0.16 + 0.01) / 3, 1e-15);
        EXPECT_FALSE(m.wallTimeSpent);
    }
}

TEST(IslandMeeting, OneIslandsRecordDecodesToItsOwnFiguresSecondsAndNaNIoU) {
    MeetingInput one = island(0.5, NAN, 0.6, 0.2, {0.5, 0.25}, 0);
    one.wallTimeSpent = true;
    const MeetingResult m = decodeMeeting(encodeMeeting(one), one, 1);
    ASSERT_EQ(m.rows.size(), 2u);
    EXPECT_TRUE(std::isnan(m.rows[0].iou));
    EXPECT_EQ(m.rows[1].iou, 0.2);
    EXPECT_EQ(m.rows[0].seconds, 1.5);
    EXPECT_EQ(m.rows[1].seconds, 2.5);
    EXPECT_EQ(m.rows[1].evaluations, 200u);
    EXPECT_EQ(m.rows[0].mean, 0.375);
    EXPECT_TRUE(m.wallTimeSpent);
    EXPECT_FALSE(m.checkpointDue);
}

}  // namespace
}  // namespace shapevo
