// SyncTurns: meet when due, take the meeting's rows into the curve, decide the stop and the
// checkpoint, print progress.
#include "run/sync_turns.hpp"

#include <algorithm>

#include "island/stop_signal.hpp"

namespace shapevo {

SyncTurns::SyncTurns(TurnContext context)
    : c_(context), meetEvery_(c_.islands < 2 ? 1 : c_.s.migration.meetingEvery()) {}

TurnDecision SyncTurns::after(const IslandRow& row, std::uint32_t g) {
    const RunSettings& s = c_.s;
    sinceMeeting_.push_back(row);
    const bool byCount = c_.checkpoints.dueByCount(g);
    if (g % meetEvery_ != 0 && !byCount && g < s.population.generations) return {};
    MeetingInput in;
    in.rows.swap(sinceMeeting_);
    in.signal = stopSignalReceived();
    in.wallTimeSpent = s.wallTime > 0 && c_.clock.runSeconds() >= s.wallTime;
    in.checkpointDue = c_.checkpoints.dueByTime();  // rank 0's clock decides time-based checkpoints
    in.waitShare = c_.clock.waitShare();
    const MeetingResult m = meet(c_.mpi, in);
    bool targetReached = false;
    for (const GenerationStats& row : m.rows) {
        c_.meta.curve.push_back(row);
        targetReached = targetReached || (s.targetFitness && row.best >= *s.targetFitness);
    }
    c_.meta.generation = g;
    // a run stopped by its wall time has spent it (the clock was read after the row's time), so
    // that a resume finds it complete
    c_.meta.wallSeconds = m.wallTimeSpent ? std::max(m.rows.back().seconds, s.wallTime) : m.rows.back().seconds;
    std::string& stopReason = c_.stop.why;
    if (m.signal > 0) stopReason = signalName(m.signal), c_.stop.bySignal = true;
    else if (m.wallTimeSpent) stopReason = "the wall-time budget";
    else if (targetReached) stopReason = "reaching the target fitness";
    else if (g >= s.population.generations) stopReason = "done";
    if (c_.progress) printProgress(m);
    return {byCount || m.checkpointDue || !stopReason.empty(), !stopReason.empty()};
}

void SyncTurns::printProgress(const MeetingResult& m) {
    for (std::size_t i = 0; i < m.rows.size(); ++i) {
        const bool last = i + 1 == m.rows.size();
        if (!c_.progress->due(m.rows[i].generation, last && !c_.stop.why.empty()) || (!last && m.rows[i].generation > 20))
            continue;
        ProgressFigures f;
        f.row = m.rows[i];
        f.runSecondsBefore = c_.clock.secondsBefore();
        f.waitShareMean = m.waitShareMean, f.waitShareMax = m.waitShareMax;
        f.islands = f.islandsHeard = c_.islands;
        c_.progress->print(f);
    }
}

}  // namespace shapevo
