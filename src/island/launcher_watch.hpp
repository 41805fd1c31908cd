// LauncherWatch: a rank whose launcher dies (mpirun or srun's slurmstepd killed with -9, by an
// out-of-memory killer, with its node) stops by itself instead of living on without it. A thread
// checks every `pollSeconds` (0.1 s) whether the rank's parent is still the one it had at
// start-up (the children of a dead process are adopted by init or a subreaper, so getppid()
// changes; under srun the parent is slurmstepd) and whether MPI's link to the launcher reported
// its loss (island/launcher_link.hpp). Once the launcher is gone it calls `onLoss` (the rank's
// default: the clean-stop path of a stop signal, island/stop_signal.hpp: finish the generation,
// write a checkpoint, exit 0, releasing the run folder's lock) and, if the process is still alive
// `graceSeconds` (1.5 s) later, `onDeadline` (default: _exit(1)): a collective with a rank that
// died too never completes, and a resume started 2 s after the launcher's death must find the
// run folder free. A checkpoint cut short by that exit is never published (checkpoints are
// complete or absent), so the previous complete one stays.
// Promise: never acts while the launcher lives; `onLoss` and `onDeadline` run at most once, on
// the watch thread; once the launcher is lost the deadline holds even through the process's exit.
#pragma once
#include <sys/types.h>

#include <functional>
#include <memory>

namespace shapevo {

struct LauncherWatchTiming {
    double pollSeconds = 0.1;   ///< how often the parent is checked
    double graceSeconds = 1.5;  ///< from noticing the loss to onDeadline
};

class LauncherWatch {
public:
    /// Watches `launcher`, the parent pid the rank had at start-up.
    LauncherWatch(pid_t launcher, LauncherWatchTiming timing, std::function<void()> onLoss,
                  std::function<void()> onDeadline);
    /// With the defaults: a stop request (stop_signal.hpp's kLauncherLost), then _exit(1).
    explicit LauncherWatch(pid_t launcher);
    /// Stops the thread; once the launcher is lost the thread is left running instead, so that
    /// `onDeadline` still ends a process whose exit does not complete in time.
    ~LauncherWatch();
    LauncherWatch(const LauncherWatch&) = delete;
    LauncherWatch& operator=(const LauncherWatch&) = delete;

    /// Whether the launcher is known to be gone (thread-safe).
    bool launcherLost() const;

private:
    struct Shared;
    std::shared_ptr<Shared> shared_;
};

}  // namespace shapevo
