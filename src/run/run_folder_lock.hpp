// RunFolderLock: one writer per run folder. `run` and `resume` hold an exclusive flock(2) on
// RUN_DIR/.lock for as long as they run; the OS releases it when the process ends in any way
// (kill -9 included), so a requeued job is never blocked by a dead one. A second writer is
// refused at once with the holder's host and pid, which the holder writes into the file.
#pragma once
#include <string>

namespace shapevo {

class RunFolderLock {
public:
    RunFolderLock() = default;
    /// Takes the lock on `runDir`. @throw InputError naming the folder and the holder (host, pid)
    /// when another process holds it, or when the lock file cannot be created.
    explicit RunFolderLock(const std::string& runDir);
    RunFolderLock(RunFolderLock&& o) noexcept;
    RunFolderLock& operator=(RunFolderLock&& o) noexcept;
    RunFolderLock(const RunFolderLock&) = delete;
    RunFolderLock& operator=(const RunFolderLock&) = delete;
    ~RunFolderLock();

private:
    int fd_ = -1;
};

}  // namespace shapevo
