// curve.csv: one row per generation with the best model's IoU as the last column, written as the
// shortest text that reads back exactly, and empty where the IoU was not measured.
#include <gtest/gtest.h>

#include <limits>

#include "report/run_report.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

TEST(CurveCsv, HasAnIoUColumnEmptyWhereNotMeasured) {
    test::TempDir dir;
    std::vector<GenerationStats> curve(2);
    curve[0] = {1, 0.5, 40, 0.25, 0.125, 0.0625, 0.8125};
    curve[1] = {2, 1.0, 80, 0.5, 0.25, 0.125, std::numeric_limits<double>::quiet_NaN()};
    writeCurveCsv(curve, dir.file("curve.csv"));
    EXPECT_EQ(test::readFile(dir.file("curve.csv")),
              "generation,seconds,evaluations,best,mean,std,iou\n"
              "1,0.500000,40,0.25,0.125,0.0625,0.8125\n"
              "2,1.000000,80,0.5,0.25,0.125,\n");
}

}  // namespace
}  // namespace shapevo
