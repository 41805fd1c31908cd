// MpiSession: MPI for the lifetime of the program, only when launched by mpirun/srun. A plain
// `shapevo run` (one island) never initialises MPI, so it starts fast and needs no launcher.
// The collective helpers below work in both cases (with one rank they are trivial). Every
// blocking call adds its time to waitedSeconds(): the time this rank spent waiting for others.
// Under a launcher the session also watches it (island/launcher_watch.hpp): a rank whose launcher
// dies stops cleanly within a bounded time, and then skips MPI_Finalize (which needs the launcher).
// A rank's output goes through its launcher, so SIGPIPE is ignored: once the launcher is gone,
// writing fails instead of killing the rank.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shapevo {

class LauncherWatch;

class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool active() const { return active_; }

    /// True on every rank if `ok` is true on every rank.
    bool allTrue(bool ok) const;
    /// True on every rank if `flag` is true on any rank.
    bool anyTrue(bool flag) const;
    /// Element-wise sums / maxima over all ranks, in place.
    void sum(std::vector<double>& values) const;
    void max(std::vector<double>& values) const;
    /// The rank holding the largest value (lowest rank among equals) and that value.
    std::pair<double, int> maxLoc(double value) const;
    /// Send `words` from rank `from` to rank `to` (no-op when from == to); returns what `to` got.
    std::vector<std::uint32_t> transfer(const std::vector<std::uint32_t>& words, int from, int to) const;
    /// Rank 0's value of `flag`, on every rank.
    bool fromRoot(bool flag) const;
    /// Broadcast a string from rank 0.
    std::string broadcast(const std::string& s) const;
    /// Seconds this rank has spent in blocking calls with other ranks (collectives, blocking
    /// receives): the helpers above add theirs, other island code adds its own with addWaited.
    double waitedSeconds() const { return waited_; }
    void addWaited(double seconds) const { waited_ += seconds; }
    /// End every rank now (MPI_Abort) when MPI is active; otherwise exit.
    [[noreturn]] void abort(int code) const;

private:
    std::unique_ptr<LauncherWatch> watch_;  ///< only under a launcher
    bool active_ = false;
    int rank_ = 0, size_ = 1;
    mutable double waited_ = 0;
};

/// Adds the time from its construction to its destruction to a session's waited seconds.
class WaitTimer {
public:
    explicit WaitTimer(const MpiSession& mpi);
    ~WaitTimer();
    WaitTimer(const WaitTimer&) = delete;
    WaitTimer& operator=(const WaitTimer&) = delete;

private:
    const MpiSession& mpi_;
    double start_;
};

/// True if the environment says a launcher (mpirun, srun) started this process.
bool launchedByMpi();

}  // namespace shapevo
