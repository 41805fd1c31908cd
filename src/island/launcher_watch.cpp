// LauncherWatch: one thread, a condition variable for prompt shutdown, state shared with the
// thread through a shared_ptr so that a detached thread never outlives what it reads.
#include "island/launcher_watch.hpp"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "island/launcher_link.hpp"
#include "island/stop_signal.hpp"

namespace shapevo {

struct LauncherWatch::Shared {
    pid_t launcher = 0;
    LauncherWatchTiming timing;
    std::function<void()> onLoss, onDeadline;
    mutable std::mutex mutex;
    std::condition_variable wake;
    bool lost = false, finished = false;
    std::thread thread;

    bool launcherGone() const { return ::getppid() != launcher || launcherLinkLost(); }

    static void watch(const std::shared_ptr<Shared>& self) {
        using Seconds = std::chrono::duration<double>;
        std::unique_lock lock(self->mutex);
        while (!self->finished && !self->lost) {
            self->wake.wait_for(lock, Seconds(self->timing.pollSeconds));
            if (!self->finished && self->launcherGone()) self->lost = true;
        }
        if (self->finished) return;
        lock.unlock();
        self->onLoss();
        lock.lock();
        // Only a normal end of the watch (finished) is waited for; after a loss the destructor
        // leaves the thread running, so this wait lasts until the deadline or the process's end.
        if (self->wake.wait_for(lock, Seconds(self->timing.graceSeconds), [&] { return self->finished; })) return;
        lock.unlock();
        self->onDeadline();
    }
};

LauncherWatch::LauncherWatch(pid_t launcher, LauncherWatchTiming timing, std::function<void()> onLoss,
                             std::function<void()> onDeadline)
    : shared_(std::make_shared<Shared>()) {
    shared_->launcher = launcher;
    shared_->timing = timing;
    shared_->onLoss = std::move(onLoss);
    shared_->onDeadline = std::move(onDeadline);
    shared_->thread = std::thread([s = shared_] { Shared::watch(s); });
}

LauncherWatch::LauncherWatch(pid_t launcher)
    : LauncherWatch(launcher, LauncherWatchTiming{}, [] { requestStop(kLauncherLost); }, [] { ::_exit(1); }) {}

LauncherWatch::~LauncherWatch() {
    std::unique_lock lock(shared_->mutex);
    if (shared_->lost) {
        lock.unlock();
        shared_->thread.detach();
        return;
    }
    shared_->finished = true;
    lock.unlock();
    shared_->wake.notify_all();
    shared_->thread.join();
}

bool LauncherWatch::launcherLost() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->lost;
}

}  // namespace shapevo
