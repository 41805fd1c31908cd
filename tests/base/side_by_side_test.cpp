// runSideBySide: the jobs run at the same time, every one runs to its end even when another
// throws, and the first failure in list order is what the caller sees.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>

#include "base/side_by_side.hpp"

namespace shapevo {
namespace {

TEST(SideBySide, TheJobsRunAtTheSameTime) {
    // Each job waits for the other's signal: one after the other, the first would time out.
    std::promise<void> firstStarted, secondStarted;
    std::future<void> seenByFirst = secondStarted.get_future(), seenBySecond = firstStarted.get_future();
    bool firstSaw = false, secondSaw = false;
    runSideBySide({[&] {
                       firstStarted.set_value();
                       firstSaw = seenByFirst.wait_for(std::chrono::seconds(10)) == std::future_status::ready;
                   },
                   [&] {
                       secondStarted.set_value();
                       secondSaw = seenBySecond.wait_for(std::chrono::seconds(10)) == std::future_status::ready;
                   }});
    EXPECT_TRUE(firstSaw);
    EXPECT_TRUE(secondSaw);
}

TEST(SideBySide, EveryJobRunsAndTheFirstFailureInListOrderIsRethrown) {
    std::atomic<int> ran{0};
    try {
        runSideBySide({[&] { ++ran; },
                       [&] {
                           ++ran;
                           throw std::runtime_error("second");
                       },
                       [&] { ++ran; },
                       [&] {
                           ++ran;
                           throw std::logic_error("fourth");
                       }});
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "second");
    }
    EXPECT_EQ(ran.load(), 4);
}

TEST(SideBySide, NoJobsIsNothing) { EXPECT_NO_THROW(runSideBySide({})); }

}  // namespace
}  // namespace shapevo
