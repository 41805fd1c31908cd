// AsyncTurns: post or collect the islands' figures, combine them on rank 0 into the run's row,
// decide and give the orders, follow them.
#include "run/async_turns.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "island/stop_signal.hpp"

namespace shapevo {

namespace {

/// The run's figures as rank 0 knows them from every island's newest status.
struct HeardFigures {
    GenerationStats global;  ///< the run's curve row (generation and seconds: rank 0's)
    int heard = 0;           ///< islands heard from at least once
    double waitSum = 0, waitMax = 0;
    double oldest = 0;       ///< age in seconds of the oldest status used
    int anySignal = 0;       ///< a stop signal any island received (0 = none)
    bool allFinished = true;
};

HeardFigures combineStatuses(const AsyncControl& control, int islands) {
    HeardFigures h;
    GenerationStats& global = h.global;
    double sum = 0, squares = 0, count = 0, evaluations = 0, iou = -1;
    global.best = -std::numeric_limits<double>::infinity();
    for (int r = 0; r < islands; ++r) {
        const double age = control.ageSeconds(r);
        if (age < 0) {
            h.allFinished = false;
            continue;
        }
        const IslandStatus& k = control.newest(r);
        ++h.heard;
        h.oldest = std::max(h.oldest, age);
        sum += k.fitnessSum, squares += k.fitnessSquares, count += k.individuals, evaluations += k.evaluations;
        h.waitSum += k.waitShare, h.waitMax = std::max(h.waitMax, k.waitShare);
        h.anySignal = std::max(h.anySignal, int(k.signal));
        h.allFinished = h.allFinished && k.finished > 0;
        if (k.best > global.best) global.best = k.best, iou = k.iou;
        else if (k.best == global.best) iou = std::max(iou, k.iou);
    }
    global.mean = sum / count;
    global.std = std::sqrt(std::max(0.0, squares / count - global.mean * global.mean));
    global.evaluations = std::uint64_t(evaluations);
    global.iou = iou >= 0 ? iou : std::numeric_limits<double>::quiet_NaN();
    return h;
}

}  // namespace

AsyncTurns::AsyncTurns(TurnContext context) : c_(context), control_(c_.mpi, 0.2) {}

TurnDecision AsyncTurns::after(const IslandRow& row, std::uint32_t generation, std::uint64_t evaluations) {
    const int signal = stopSignalReceived();
    const bool finished = generation >= c_.s.population.generations;
    IslandStatus own;
    own.generation = generation;
    own.seconds = row.stats.seconds;
    own.best = row.stats.best;
    own.iou = std::isnan(row.stats.iou) ? -1.0 : row.stats.iou;
    own.fitnessSum = row.fitnessSum, own.fitnessSquares = row.fitnessSquares;
    own.individuals = row.individuals;
    own.evaluations = double(evaluations);
    own.waitShare = c_.clock.waitShare();
    own.signal = signal;
    own.finished = finished ? 1 : 0;
    std::optional<AsyncOrder> order;
    if (c_.mpi.rank() != 0) {
        control_.report(own, (signal && !toldSignal_) || (finished && !toldFinished_));
        toldSignal_ = toldSignal_ || signal, toldFinished_ = toldFinished_ || finished;
        order = control_.poll();
    } else {
        order = decide(own, generation);
    }
    if (!order) return {};
    if (order->kind == AsyncOrder::Stop && c_.mpi.rank() != 0) {
        c_.stop.bySignal = order->signal > 0;
        c_.stop.why = c_.stop.bySignal ? signalName(order->signal) : "the order of rank 0";
    }
    c_.meta.generation = order->generation;  // every rank names the checkpoint after rank 0's generation
    return {true, order->kind == AsyncOrder::Stop};
}

std::optional<AsyncOrder> AsyncTurns::decide(const IslandStatus& own, std::uint32_t generation) {
    const RunSettings& s = c_.s;
    control_.collect(own);
    const double seconds = c_.clock.runSeconds();
    HeardFigures h = combineStatuses(control_, c_.islands);
    GenerationStats& global = h.global;
    global.generation = generation;
    global.seconds = seconds;
    c_.meta.curve.push_back(global);  // one row per rank-0 generation
    c_.meta.generation = generation;
    c_.meta.wallSeconds = global.seconds;
    std::string& stopReason = c_.stop.why;
    if (h.anySignal > 0) stopReason = signalName(h.anySignal), c_.stop.bySignal = true;
    else if (s.wallTime > 0 && global.seconds >= s.wallTime) stopReason = "the wall-time budget";
    else if (s.targetFitness && global.best >= *s.targetFitness) stopReason = "reaching the target fitness";
    else if (h.allFinished) stopReason = "done";
    std::optional<AsyncOrder> order;
    if (!stopReason.empty()) order = AsyncOrder{AsyncOrder::Stop, h.anySignal, c_.meta.generation};
    else if (c_.checkpoints.dueByCount(generation) || c_.checkpoints.dueByTime())
        order = AsyncOrder{AsyncOrder::Checkpoint, 0, c_.meta.generation};
    if (order) control_.order(*order);
    if (c_.progress && c_.progress->due(global.generation, !stopReason.empty())) {
        ProgressFigures f;
        f.row = global;
        f.runSecondsBefore = c_.clock.secondsBefore();
        f.waitShareMean = h.waitSum / std::max(1, h.heard), f.waitShareMax = h.waitMax;
        f.islands = c_.islands, f.islandsHeard = h.heard;
        f.oldestAgeSeconds = h.oldest;
        c_.progress->print(f);
    }
    return order;
}

}  // namespace shapevo
