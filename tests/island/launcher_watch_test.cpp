// LauncherWatch: it never acts while the rank's parent is its launcher; once the parent is another
// process it calls onLoss, then onDeadline after the grace period, each once, in that order; a
// launcher lost is a stop request of its own name (the clean-stop path of the stop signals).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "island/launcher_watch.hpp"
#include "island/stop_signal.hpp"

namespace shapevo {
namespace {

struct LauncherWatchCalls {
    std::atomic<int> losses{0}, deadlines{0};
    std::atomic<bool> lossBeforeDeadline{false};
};

/// Waits up to 10 s for `done`.
template <class F>
bool launcherWatchEventually(F done) {
    for (int i = 0; i < 1000 && !done(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return done();
}

TEST(LauncherWatch, NeverActsWhileTheParentIsTheLauncher) {
    auto calls = std::make_shared<LauncherWatchCalls>();
    {
        LauncherWatch watch(::getppid(), LauncherWatchTiming{0.005, 0.01}, [calls] { ++calls->losses; },
                            [calls] { ++calls->deadlines; });
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        EXPECT_FALSE(watch.launcherLost());
    }
    EXPECT_EQ(calls->losses, 0);
    EXPECT_EQ(calls->deadlines, 0);
}

TEST(LauncherWatch, AnotherParentMeansTheLauncherIsLostThenTheDeadlineComes) {
    auto calls = std::make_shared<LauncherWatchCalls>();
    // this process's own pid is never its parent: as if the launcher had died before the first check
    LauncherWatch watch(::getpid(), LauncherWatchTiming{0.005, 0.05}, [calls] { ++calls->losses; },
                        [calls] {
                            calls->lossBeforeDeadline = calls->losses == 1;
                            ++calls->deadlines;
                        });
    ASSERT_TRUE(launcherWatchEventually([&] { return calls->deadlines > 0; }));
    EXPECT_TRUE(watch.launcherLost());
    EXPECT_TRUE(calls->lossBeforeDeadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(calls->losses, 1);
    EXPECT_EQ(calls->deadlines, 1);
}

TEST(LauncherWatch, ALostLauncherIsAStopRequestOfItsOwnName) {
    const int before = stopSignalReceived();
    requestStop(kLauncherLost);
    EXPECT_EQ(stopSignalReceived(), kLauncherLost);
    requestStop(before);  // other tests of this process run islands in-process
    EXPECT_STREQ(signalName(kLauncherLost), "the loss of its launcher (mpirun or srun)");
    EXPECT_GT(kLauncherLost, 64) << "no signal may have its number";
}

}  // namespace
}  // namespace shapevo
