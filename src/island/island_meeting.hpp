// IslandMeeting: in sync mode the islands meet every `migration.meeting_interval` generations
// (and whenever a checkpoint is due or the run reaches its last generation) instead of every
// generation. Each brings the figures of every generation since the last meeting, its stop
// signal, whether its wall-time budget is spent, rank 0's time-based checkpoint request and its
// waiting; one all-reduce (a user-defined MPI operation over one record) turns them into the
// run's curve rows for those generations and the decisions everybody acts on.
// Promise: the rows are exactly those a per-generation reduction gives (sums of each generation's
// figures, the largest best and the IoU of the island that holds it), so a seeded run's curve does
// not depend on how often the islands meet; with one rank (or without MPI) meeting is free.
#pragma once
#include <cstdint>
#include <vector>

#include "island/mpi_session.hpp"
#include "search/generation_stats.hpp"

namespace shapevo {

/// One island's figures of one generation.
struct IslandRow {
    GenerationStats stats;     ///< best, iou (NaN = not measured), seconds, evaluations of this island
    double fitnessSum = 0, fitnessSquares = 0, individuals = 0;
};

struct MeetingInput {
    std::vector<IslandRow> rows;  ///< the generations since the last meeting (the same on every rank)
    int signal = 0;               ///< a stop signal this rank received (0 = none)
    bool wallTimeSpent = false;   ///< this rank's clock says the wall-time budget is spent
    bool checkpointDue = false;   ///< rank 0's clock says a time-based checkpoint is due
    double waitShare = 0;         ///< this rank's waiting so far over its wall time
};

struct MeetingResult {
    std::vector<GenerationStats> rows;  ///< the run's curve rows (seconds: this rank's own)
    int signal = 0;
    bool wallTimeSpent = false, checkpointDue = false;
    double waitShareMax = 0, waitShareMean = 0;  ///< over the ranks
};

/// The figures of a whole population for one generation.
IslandRow islandRow(const GenerationStats& stats, const std::vector<double>& fitness);

/// Collective on every rank (trivial without MPI). Counts its time as waiting.
MeetingResult meet(const MpiSession& mpi, const MeetingInput& in);

/// The record meet() reduces, and how two records combine (exposed for tests).
std::vector<double> encodeMeeting(const MeetingInput& in);
void combineMeetings(const double* in, double* inout);
MeetingResult decodeMeeting(const std::vector<double>& record, const MeetingInput& own, int ranks);

}  // namespace shapevo
