// runSideBySide: independent jobs run at the same time, one thread each, and the caller waits for
// all of them. Meant for writing a batch of independent files: each atomic write waits for the
// disk twice (base/atomic_write.hpp: fsync of the file, then of its folder), and waits that
// overlap are committed together by the file system, while the jobs that draw or compress keep
// every core busy.
// Promises: every job runs to its end, whatever the others do; the call returns once all have
// ended and then rethrows the exception of the first job, in list order, that threw (the others'
// are dropped). A job whose thread cannot be started runs on the calling thread. Jobs must not
// share mutable state. Plain threads rather than TBB tasks: a task blocked in fsync would hold
// one of TBB's workers (one per core) and so keep the other writes waiting.
#pragma once
#include <functional>
#include <vector>

namespace shapevo {

void runSideBySide(const std::vector<std::function<void()>>& jobs);

}  // namespace shapevo
