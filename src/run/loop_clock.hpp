// LoopClock: the island loop's sense of time: the run's wall seconds (this session's plus those of
// the sessions before a resume) and the share of this session that this rank spent waiting for
// other ranks (MpiSession::waitedSeconds counted from the clock's start).
#pragma once
#include <algorithm>
#include <chrono>

#include "island/mpi_session.hpp"

namespace shapevo {

class LoopClock {
public:
    using Clock = std::chrono::steady_clock;

    /// Starts now; `secondsBefore`: the run's wall time in earlier sessions (0 for a new run).
    LoopClock(const MpiSession& mpi, double secondsBefore)
        : mpi_(mpi), start_(Clock::now()), secondsBefore_(secondsBefore), waitedBefore_(mpi.waitedSeconds()) {}

    static double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

    double secondsBefore() const { return secondsBefore_; }
    /// This session's seconds so far.
    double sessionSeconds() const { return since(start_); }
    /// The run's wall seconds so far, over every session.
    double runSeconds() const { return secondsBefore_ + sessionSeconds(); }
    /// This rank's waiting in this session over the session's wall time.
    double waitShare() const { return (mpi_.waitedSeconds() - waitedBefore_) / std::max(1e-9, sessionSeconds()); }

private:
    const MpiSession& mpi_;
    Clock::time_point start_;
    double secondsBefore_;
    double waitedBefore_;
};

}  // namespace shapevo
