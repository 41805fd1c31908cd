// AsyncTurns: the turn after each generation in async mode (two islands or more). Nobody waits:
// every rank but 0 posts its newest figures to rank 0 (island/async_control.hpp) and takes rank
// 0's orders; rank 0 combines the newest figures it has heard into the run's curve row of its own
// generation, decides whether and why the run stops and when a checkpoint is due, gives those
// orders, and prints the progress lines. The run stops ("done") once every island has done its
// generations: an island that has done them goes on evolving (and reporting) until rank 0's stop
// order reaches it, so none waits for the slowest.
// Promise: no rank waits for another except in a checkpoint and at the end; every rank names a
// checkpoint after rank 0's generation. finish() is collective and must be called on every rank
// in either mode (it completes every message posted).
#pragma once
#include <cstdint>
#include <optional>

#include "island/async_control.hpp"
#include "island/island_meeting.hpp"
#include "run/island_turn.hpp"

namespace shapevo {

class AsyncTurns {
public:
    explicit AsyncTurns(TurnContext context);
    /// After generation `generation`, with this island's figures `row` and evaluations so far.
    TurnDecision after(const IslandRow& row, std::uint32_t generation, std::uint64_t evaluations);
    /// Collective, on every rank: complete every posted status and order.
    void finish() { control_.finish(); }

private:
    /// Rank 0: hear the others, take the curve row, decide; the order it gave, if any.
    std::optional<AsyncOrder> decide(const IslandStatus& own, std::uint32_t generation);

    TurnContext c_;
    AsyncControl control_;
    bool toldFinished_ = false, toldSignal_ = false;
};

}  // namespace shapevo
