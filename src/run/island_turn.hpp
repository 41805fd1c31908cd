// The turn every island takes after each generation, in either migration mode (sync:
// run/sync_turns.hpp, async: run/async_turns.hpp): what it reads (settings, clock, checkpoint
// timing), what it updates (the run's curve, its generation and time, why the run stops) and what
// it decides (write a checkpoint now; stop).
#pragma once
#include <string>

#include "checkpoint/island_state.hpp"
#include "island/mpi_session.hpp"
#include "run/island_checkpoints.hpp"
#include "run/loop_clock.hpp"
#include "run/progress_line.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// Why the run stops: empty while it goes on; otherwise "done", "the wall-time budget",
/// "reaching the target fitness", "the order of rank 0" or a signal's name (bySignal).
struct StopReason {
    std::string why;
    bool bySignal = false;
};

struct TurnContext {
    const MpiSession& mpi;
    const RunSettings& s;
    const LoopClock& clock;
    const IslandCheckpoints& checkpoints;
    ProgressLine* progress;  ///< rank 0's progress lines; null on the other ranks and when quiet
    int islands;             ///< 1 without MPI
    RunMetadata& meta;       ///< its curve, generation and wallSeconds: what a checkpoint holds
    StopReason& stop;
};

/// What a turn decided: write a checkpoint now (collectively, named after meta.generation), and
/// whether the run stops after it (a stop always comes with a checkpoint).
struct TurnDecision {
    bool checkpoint = false;
    bool stop = false;
};

}  // namespace shapevo
