// IslandCheckpoints: when the run's next checkpoint is due and how the islands write it. A
// checkpoint is complete or absent: every rank writes its island into a partial folder, all agree,
// then rank 0 adds run.h5 and MANIFEST, publishes it with one rename and prunes the old ones
// (checkpoint.keep stay); the previous complete checkpoint stays until the new one is published.
// Promise: a checkpoint that cannot be written stops the run on every rank (RunFailure, whose
// message on rank 0 names the newest complete checkpoint) rather than lose more work.
#pragma once
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

#include "checkpoint/checkpoint_settings.hpp"
#include "checkpoint/island_state.hpp"
#include "island/mpi_session.hpp"
#include "run/loop_clock.hpp"

namespace shapevo {

class IslandCheckpoints {
public:
    IslandCheckpoints(const MpiSession& mpi, const CheckpointSettings& settings, const std::string& folder, std::ostream& log);

    /// A checkpoint is due by generation count (checkpoint.interval) after `generation`.
    bool dueByCount(std::uint32_t generation) const;
    /// Rank 0's clock says a time-based checkpoint is due (checkpoint.seconds since the last);
    /// false on the other ranks, which learn of it from rank 0.
    bool dueByTime() const;
    /// Collective: write this rank's island, as `islandNow` makes it (which may itself be
    /// collective: its time counts as the checkpoint's), as checkpoint meta.generation of the run
    /// `meta`. @throw RunFailure on every rank if any part could not be written.
    void write(const std::function<IslandState()>& islandNow, const RunMetadata& meta);

    double seconds() const { return seconds_; }              ///< this rank's time in checkpoints
    double waitedSeconds() const { return waitedSeconds_; }  ///< the part of it spent waiting

private:
    const MpiSession& mpi_;
    CheckpointSettings settings_;
    std::string folder_;
    std::ostream& log_;
    LoopClock::Clock::time_point last_;
    double seconds_ = 0, waitedSeconds_ = 0;
};

}  // namespace shapevo
