// SyncTurns: the turn after each generation in sync mode (and in any one-island run). The islands
// meet every `migration.meeting_interval` generations, when a checkpoint is due by generation count
// and at the last generation (island/island_meeting.hpp); a meeting adds the run's curve rows of
// the generations since the last one, agrees whether and why the run stops (a signal, the wall-time
// budget, the target fitness, the last generation) and whether a checkpoint is written now, and
// prints rank 0's progress lines.
// Promise: every rank decides the same at the same generation, so a seeded run repeats byte for
// byte and its curve does not depend on how often the islands meet.
#pragma once
#include <cstdint>
#include <vector>

#include "island/island_meeting.hpp"
#include "run/island_turn.hpp"

namespace shapevo {

class SyncTurns {
public:
    explicit SyncTurns(TurnContext context);
    /// After generation `generation`, whose figures on this island are `row`; collective when
    /// the islands meet.
    TurnDecision after(const IslandRow& row, std::uint32_t generation);

private:
    /// Rank 0: the progress lines for the rows of meeting `m`.
    void printProgress(const MeetingResult& m);

    TurnContext c_;
    std::uint32_t meetEvery_;
    std::vector<IslandRow> sinceMeeting_;
};

}  // namespace shapevo
