// AsyncControl: async mode's only way for islands to learn of each other, without ever waiting.
// Every rank but 0 posts its newest figures to rank 0 with a non-blocking send (at most one every
// `cadence` seconds, at once when it has a stop signal or has finished its generations); rank 0
// takes whatever has arrived, keeps the newest figures of every island with their arrival time,
// decides, and posts its orders (write a checkpoint now, stop) to every rank, which take them
// at their next generation boundary. Only the orders' consequences wait: a checkpoint and the
// end of the run are collective.
// Promise: no call here blocks except finish(), which completes every posted message (so
// MPI_Finalize never meets one in flight) and is collective.
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "island/mpi_session.hpp"
#include "island/posted_sends.hpp"

namespace shapevo {

/// One island's newest figures, as rank 0 knows them.
struct IslandStatus {
    double generation = 0, seconds = 0, best = 0, iou = -1;  ///< iou -1 = not measured
    double fitnessSum = 0, fitnessSquares = 0, individuals = 0, evaluations = 0;
    double waitShare = 0;  ///< waiting so far over wall time
    double signal = 0;     ///< a stop signal the island received (0 = none)
    double finished = 0;   ///< 1 once the island has done all its generations
};

struct AsyncOrder {
    enum Kind { Checkpoint = 1, Stop = 2 } kind = Checkpoint;
    int signal = 0;  ///< Stop: the signal that stopped the run (0 = another reason)
    std::uint32_t generation = 0;  ///< rank 0's generation: the checkpoint's name on every rank
};

class AsyncControl {
public:
    using Clock = std::chrono::steady_clock;
    AsyncControl(const MpiSession& mpi, double cadenceSeconds);
    AsyncControl(const AsyncControl&) = delete;
    AsyncControl& operator=(const AsyncControl&) = delete;

    /// Ranks but 0: post `s` if `cadence` has passed since the last post, or `urgent`.
    void report(const IslandStatus& s, bool urgent);
    /// Rank 0: its own figures, then every status that has arrived.
    void collect(const IslandStatus& own);
    /// Rank 0: the newest figures of island r and their age in seconds (own: 0).
    const IslandStatus& newest(int rank) const { return known_[std::size_t(rank)]; }
    double ageSeconds(int rank) const;
    bool heardFromAll() const;  ///< rank 0 has figures of every island
    /// Rank 0: post an order to every other rank.
    void order(const AsyncOrder& o);
    /// Ranks but 0: the order that has arrived, if any (never blocks).
    std::optional<AsyncOrder> poll();
    /// Collective: complete every posted message, discard late statuses.
    void finish();

private:
    void receiveStatuses();

    const MpiSession& mpi_;
    double cadence_;
    Clock::time_point lastReport_{};
    bool reportedOnce_ = false;
    std::vector<IslandStatus> known_;
    std::vector<Clock::time_point> heard_;
    std::vector<bool> heardAny_;
    PostedSends sends_;
};

}  // namespace shapevo
