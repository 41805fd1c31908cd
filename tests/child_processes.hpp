// Child processes of this process, for tests and fuzz targets that check that code which forks
// (the mesh import sandbox) leaves no process behind. Promises: childProcesses() lists every
// child of every thread, running or ended but not yet reaped (a zombie is still its parent's
// child), read from Linux's /proc/self/task/<tid>/children; ChildProcessWatch reports the children
// that appeared since it was made, so children the process had before (such as the
// llvm-symbolizer that the sanitizer runtime starts once and keeps, e.g. when libFuzzer prints
// NEW_FUNC) do not count. "No child at all" (waitpid(-1, WNOHANG) failing with ECHILD) is not
// the same promise and is false in such processes.
#pragma once
#include <sys/types.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace shapevo::test {

/// This process's children, sorted. Throws std::runtime_error if /proc does not list them (a
/// kernel without CONFIG_PROC_CHILDREN): a check built on it must not pass for want of a list.
inline std::vector<pid_t> childProcesses() {
    std::vector<pid_t> children;
    std::error_code ec;
    bool listed = false;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
        std::FILE* f = std::fopen((task.path() / "children").c_str(), "r");
        if (!f) continue;  // the thread ended meanwhile
        listed = true;
        long pid = 0;
        while (std::fscanf(f, "%ld", &pid) == 1) children.push_back(pid_t(pid));
        std::fclose(f);
    }
    if (!listed) throw std::runtime_error("cannot list this process's children (/proc/self/task/*/children)");
    std::sort(children.begin(), children.end());
    children.erase(std::unique(children.begin(), children.end()), children.end());
    return children;
}

/// Remembers the children there are when it is made; newChildren() lists those there are now
/// that were not (started since and still running, or ended and not reaped).
class ChildProcessWatch {
public:
    ChildProcessWatch() : before_(childProcesses()) {}
    std::vector<pid_t> newChildren() const {
        std::vector<pid_t> now = childProcesses(), added;
        std::set_difference(now.begin(), now.end(), before_.begin(), before_.end(), std::back_inserter(added));
        return added;
    }

private:
    std::vector<pid_t> before_;
};

}  // namespace shapevo::test
