// islandLoop: generations, migration, global statistics, agreed stopping, checkpoints, outputs.
// Sync mode: the islands meet every few generations (island/island_meeting.hpp); async mode:
// rank 0 hears statuses and gives orders without anyone waiting (island/async_control.hpp).
#include "run/island_loop.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <ostream>
#include <thread>

#include "base/peak_memory.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/run_identity.hpp"
#include "run/diagnostics_log.hpp"
#include "report/curve_plot.hpp"
#include "genome/genome_file.hpp"
#include "mesh/glb_writer.hpp"
#include "report/model_writer.hpp"
#include "report/render/model_picture.hpp"
#include "report/run_report.hpp"
#include "island/async_control.hpp"
#include "island/island_meeting.hpp"
#include "island/ring_migration.hpp"
#include "island/stop_signal.hpp"
#include "run/progress_line.hpp"
#include "search/search_methods.hpp"

namespace shapevo {

namespace {

using Clock = std::chrono::steady_clock;

/// Island r's seed: r = 0 keeps the run's seed, so a one-rank MPI run equals a plain run.
std::uint64_t islandSeed(std::uint64_t seed, int rank) { return seed + 0x9e3779b97f4a7c15ULL * std::uint64_t(rank); }

/// Every rank writes its island into the partial folder; once all have, rank 0 adds run.h5 and
/// MANIFEST and publishes it with one rename. Returns "" on success; otherwise, on rank 0, why not
/// (every rank learns of the failure: the result's emptiness is agreed).
std::string writeCheckpoint(const MpiSession& mpi, const std::string& folder, const IslandState& island,
                            const RunMetadata& meta, int keep, std::ostream& log) {
    namespace fs = std::filesystem;
    const std::string name = checkpointName(meta.generation);
    const std::string partial = folder + "/." + name + ".partial", published = folder + "/" + name;
    std::string problem;
    if (mpi.rank() == 0) {
        std::error_code ec;
        fs::remove_all(partial, ec);
        fs::create_directories(partial, ec);
        if (ec) problem = "cannot create " + partial + ": " + ec.message();
    }
    if (!mpi.fromRoot(problem.empty())) return mpi.rank() == 0 ? problem : "failed on rank 0";
    try {
        writeIslandFile(partial + "/" + islandFileName(mpi.rank()), island);
    } catch (const std::exception& e) {
        problem = e.what();
    }
    if (!mpi.allTrue(problem.empty())) {
        if (!problem.empty()) log << "shapevo: rank " << mpi.rank() << " could not write its island: " << problem << "\n";
        if (mpi.rank() == 0) {
            std::error_code ec;
            fs::remove_all(partial, ec);
            if (problem.empty()) problem = "another rank could not write its island (it says why)";
        }
        return mpi.rank() == 0 ? problem : "failed";
    }
    if (mpi.rank() == 0) {
        try {
            writeRunMetadata(partial + "/run.h5", meta);
            std::vector<std::string> files{"run.h5"};
            for (int r = 0; r < mpi.size(); ++r) files.push_back(islandFileName(r));
            writeManifest(partial, files);
            publishCheckpoint(partial, published, meta.runId);
            pruneCheckpoints(folder, keep, meta.runId);
        } catch (const std::exception& e) {
            std::error_code ec;
            fs::remove_all(partial, ec);
            problem = e.what();
        }
    }
    return mpi.fromRoot(problem.empty()) ? "" : mpi.rank() == 0 ? problem : "failed";
}

/// The IoU of an island's best model, for the curve and the progress line. It is scored again only
/// when the best model changes (often early in a run, rarely later: ~400 of 1,100 generations in
/// tree-logo's first 20 s), on the loop's thread between generations, in one kept workspace; the
/// time goes to summary.json's iou_seconds (~0.3 % of the run). IoU is derived data: scoring draws
/// no random number, and what it adds to the scorer's anomaly counts is kept here so that
/// summary.json counts only the search's evaluations.
class BestModelIoU {
public:
    double of(const Scene& scene, const Chromosome& best) {
        if (!known_ || !(best == model_)) {
            const auto start = Clock::now();
            const Scorer::Anomalies before = scene.scorer().anomalies();
            if (!workspace_) workspace_ = scene.scorer().makePlainWorkspace();
            iou_ = scene.iou(best, *workspace_);
            const Scorer::Anomalies after = scene.scorer().anomalies();
            added_.nonFinite += after.nonFinite - before.nonFinite;
            added_.truncated += after.truncated - before.truncated;
            model_ = best;
            known_ = true;
            seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
        }
        return iou_;
    }
    const Scorer::Anomalies& addedAnomalies() const { return added_; }
    double seconds() const { return seconds_; }  ///< time spent scoring for IoU

private:
    Chromosome model_;
    std::unique_ptr<ScoreWorkspace> workspace_;
    double iou_ = 0, seconds_ = 0;
    bool known_ = false;
    Scorer::Anomalies added_;
};

/// What a user needs after a failed checkpoint: the newest complete checkpoint of this run.
std::string newestCompleteCheckpoint(const std::string& folder, const std::string& runId) {
    for (const std::string& c : listCheckpoints(folder))
        if (verifyCheckpoint(c).empty() && checkpointRunId(c) == runId) return "the newest complete checkpoint is " + c + "; resume from it once fixed";
    return "there is no complete checkpoint of this run yet";
}

}  // namespace

JobResult islandLoop(const MpiSession& mpi, const RunSettings& s, const Grammar& grammar, const Scene& scene,
                     const std::string& folder, RunMetadata meta, const IslandState* restored, const JobOptions& options,
                     std::ostream& log) {
    const auto start = Clock::now();
    const double wallBefore = meta.wallSeconds;
    auto elapsed = [&] { return wallBefore + std::chrono::duration<double>(Clock::now() - start).count(); };
    const bool root = mpi.rank() == 0;
    Evaluator evaluator(scene.scorer(), s.threads);
    const Scorer::Anomalies anomaliesBefore = scene.scorer().anomalies();  // the start-up checks' models do not count
    const std::unique_ptr<SearchMethod> method = makeSearchMethod(s.search, s.ga, grammar, s.limits, islandSeed(s.seed, mpi.rank()));
    SearchMethod& ga = *method;
    RingMigration migration(mpi, s.migration, grammar, s.limits);
    if (restored) migration.restoreArrivals(restored->arrivals);
    installStopSignalHandlers();
    std::vector<GenerationStats> localCurve = restored ? restored->curve : std::vector<GenerationStats>{};
    BestModelIoU bestIoU;
    std::optional<DiagnosticsLog> diagnostics;  // search.diagnostics: rank 0's island, a row per generation
    if (root && s.search.diagnostics) diagnostics.emplace(folder + "/diagnostics.csv", grammar);

    if (root && !options.quiet)
        log << "shapevo " << (restored ? "resume " : "run ") << s.name << ": grammar " << s.grammarPath << ", target "
            << scene.description() << ", " << mpi.size() << " island(s) x " << evaluator.threads()
            << " thread(s), seed " << s.seed << ", output " << folder << "\n";

    JobResult result;
    result.folder = folder;
    std::string stopReason;  ///< empty while running
    bool bySignal = false;
    double migrationSeconds = 0, checkpointSeconds = 0;  // this rank's time in each, for the summary
    double checkpointWaited = 0;                         // the part of its waiting spent in checkpoints
    auto lastCheckpoint = Clock::now();
    auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    const double waitedBefore = mpi.waitedSeconds();
    auto waitShare = [&] { return (mpi.waitedSeconds() - waitedBefore) / std::max(1e-9, since(start)); };
    ProgressLine progress(log, s.ga.generations, s.wallTime);
    const bool showProgress = root && !options.quiet;
    const int islands = mpi.active() ? mpi.size() : 1;

    // Every rank's own part of a generation: migration, its figures, its own curve row.
    IslandRow lastRow;
    auto ownGeneration = [&] {
        const auto migrationStart = Clock::now();
        migration.afterGeneration(ga.population(), ga.generation(), ga.migrantSlots());
        migrationSeconds += since(migrationStart);
        GenerationStats local = ga.stats();
        local.seconds = elapsed();
        local.iou = bestIoU.of(scene, ga.population().individuals[ga.population().best()]);
        localCurve.push_back(local);
        lastRow = islandRow(local, ga.population().fitness);
        if (diagnostics) diagnostics->write(ga, local.seconds);
    };
    auto checkpointNow = [&] {  // collective
        const auto checkpointStart = Clock::now();
        const double waitedBefore = mpi.waitedSeconds();
        IslandState island;
        island.runId = meta.runId;
        island.seed = meta.seed;
        island.ranks = meta.ranks;
        island.rank = mpi.rank();
        island.generation = ga.generation();
        island.evaluations = ga.evaluations();
        island.rng = ga.rng().state();
        island.population = ga.population();
        island.arrivals = migration.arrivals();  // sync: receives what is still in flight to this rank
        island.curve = localCurve;
        const std::string failed = writeCheckpoint(mpi, folder, island, meta, s.checkpoint.keep, log);
        if (!failed.empty())  // every rank sees the failure: stop now rather than lose more work
            throw RunFailure{root ? "checkpoint at generation " + std::to_string(meta.generation) +
                                        " could not be written: " + failed + "; the run stops; " +
                                        newestCompleteCheckpoint(folder, meta.runId)
                                  : std::string()};
        checkpointSeconds += since(checkpointStart);
        checkpointWaited += mpi.waitedSeconds() - waitedBefore;
        lastCheckpoint = Clock::now();
    };
    auto timeForCheckpoint = [&] { return root && s.checkpoint.seconds > 0 && since(lastCheckpoint) >= s.checkpoint.seconds; };
    auto intervalCheckpoint = [&] { return s.checkpoint.interval > 0 && ga.generation() % s.checkpoint.interval == 0; };

    // Sync mode (and any one-island run): the islands meet every `meetEvery` generations, when a
    // checkpoint is due by generation count and at the last generation (island/island_meeting.hpp).
    const std::uint32_t meetEvery = islands < 2 ? 1 : s.migration.meetingEvery();
    std::vector<IslandRow> sinceMeeting;
    auto syncTurn = [&]() -> bool {
        sinceMeeting.push_back(lastRow);
        const std::uint32_t g = ga.generation();
        const bool byCount = intervalCheckpoint();
        if (g % meetEvery != 0 && !byCount && g < s.ga.generations) return false;
        MeetingInput in;
        in.rows.swap(sinceMeeting);
        in.signal = stopSignalReceived();
        in.wallTimeSpent = s.wallTime > 0 && elapsed() >= s.wallTime;
        in.checkpointDue = timeForCheckpoint();  // rank 0's clock decides time-based checkpoints
        in.waitShare = waitShare();
        const MeetingResult m = meet(mpi, in);
        bool targetReached = false;
        for (const GenerationStats& row : m.rows) {
            meta.curve.push_back(row);
            targetReached = targetReached || (s.targetFitness && row.best >= *s.targetFitness);
        }
        meta.generation = g;
        meta.wallSeconds = m.rows.back().seconds;
        if (m.signal > 0) stopReason = signalName(m.signal), bySignal = true;
        else if (m.wallTimeSpent) stopReason = "the wall-time budget";
        else if (targetReached) stopReason = "reaching the target fitness";
        else if (g >= s.ga.generations) stopReason = "done";
        if (showProgress)
            for (std::size_t i = 0; i < m.rows.size(); ++i) {
                const bool last = i + 1 == m.rows.size();
                if (!progress.due(m.rows[i].generation, last && !stopReason.empty()) || (!last && m.rows[i].generation > 20)) continue;
                ProgressFigures f;
                f.row = m.rows[i];
                f.runSecondsBefore = wallBefore;
                f.waitShareMean = m.waitShareMean, f.waitShareMax = m.waitShareMax;
                f.islands = f.islandsHeard = islands;
                progress.print(f);
            }
        if (byCount || m.checkpointDue || !stopReason.empty()) checkpointNow();
        return !stopReason.empty();
    };

    // Async mode: nobody waits; rank 0 hears the others' newest figures and gives the orders
    // (island/async_control.hpp). `idle`: this island has done its generations and waits for
    // the others (the end of the run).
    AsyncControl control(mpi, 0.2);
    bool toldFinished = false, toldSignal = false;
    auto asyncTurn = [&](bool idle) -> bool {
        const int signal = stopSignalReceived();
        const bool finished = ga.generation() >= s.ga.generations;
        IslandStatus own;
        own.generation = ga.generation();
        own.seconds = lastRow.stats.seconds;
        own.best = lastRow.stats.best;
        own.iou = std::isnan(lastRow.stats.iou) ? -1.0 : lastRow.stats.iou;
        own.fitnessSum = lastRow.fitnessSum, own.fitnessSquares = lastRow.fitnessSquares;
        own.individuals = lastRow.individuals;
        own.evaluations = double(ga.evaluations());
        own.waitShare = waitShare();
        own.signal = signal;
        own.finished = finished ? 1 : 0;
        std::optional<AsyncOrder> order;
        if (!root) {
            control.report(own, (signal && !toldSignal) || (finished && !toldFinished));
            toldSignal = toldSignal || signal, toldFinished = toldFinished || finished;
            order = control.poll();
        } else {
            control.collect(own);
            GenerationStats global;
            global.generation = ga.generation();
            global.seconds = elapsed();
            double sum = 0, squares = 0, count = 0, evaluations = 0, waitSum = 0, waitMax = 0, oldest = 0, iou = -1;
            int heard = 0, anySignal = 0;
            bool allFinished = true;
            global.best = -std::numeric_limits<double>::infinity();
            for (int r = 0; r < islands; ++r) {
                const double age = control.ageSeconds(r);
                if (age < 0) {
                    allFinished = false;
                    continue;
                }
                const IslandStatus& k = control.newest(r);
                ++heard;
                oldest = std::max(oldest, age);
                sum += k.fitnessSum, squares += k.fitnessSquares, count += k.individuals, evaluations += k.evaluations;
                waitSum += k.waitShare, waitMax = std::max(waitMax, k.waitShare);
                anySignal = std::max(anySignal, int(k.signal));
                allFinished = allFinished && k.finished > 0;
                if (k.best > global.best) global.best = k.best, iou = k.iou;
                else if (k.best == global.best) iou = std::max(iou, k.iou);
            }
            global.mean = sum / count;
            global.std = std::sqrt(std::max(0.0, squares / count - global.mean * global.mean));
            global.evaluations = std::uint64_t(evaluations);
            global.iou = iou >= 0 ? iou : std::numeric_limits<double>::quiet_NaN();
            if (!idle) meta.curve.push_back(global);  // one row per rank-0 generation
            meta.generation = ga.generation();
            meta.wallSeconds = global.seconds;
            if (anySignal > 0) stopReason = signalName(anySignal), bySignal = true;
            else if (s.wallTime > 0 && global.seconds >= s.wallTime) stopReason = "the wall-time budget";
            else if (s.targetFitness && global.best >= *s.targetFitness) stopReason = "reaching the target fitness";
            else if (allFinished) stopReason = "done";
            if (!stopReason.empty()) order = AsyncOrder{AsyncOrder::Stop, anySignal, meta.generation};
            else if ((!idle && intervalCheckpoint()) || timeForCheckpoint())
                order = AsyncOrder{AsyncOrder::Checkpoint, 0, meta.generation};
            if (order) control.order(*order);
            if (showProgress && progress.due(idle ? ~0u : global.generation, !stopReason.empty())) {
                ProgressFigures f;
                f.row = global;
                f.runSecondsBefore = wallBefore;
                f.waitShareMean = waitSum / std::max(1, heard), f.waitShareMax = waitMax;
                f.islands = islands, f.islandsHeard = heard;
                f.oldestAgeSeconds = oldest;
                progress.print(f);
            }
        }
        if (!order) return false;
        if (order->kind == AsyncOrder::Stop && !root) {
            bySignal = order->signal > 0;
            stopReason = bySignal ? signalName(order->signal) : "the order of rank 0";
        }
        meta.generation = order->generation;  // every rank names the checkpoint after rank 0's generation
        checkpointNow();
        return order->kind == AsyncOrder::Stop;
    };
    const bool async = s.migration.async && islands > 1;
    auto afterGeneration = [&]() -> bool {
        ownGeneration();
        return async ? asyncTurn(false) : syncTurn();
    };

    bool stop = false;
    if (restored) {
        ga.restore(restored->population, restored->rng, restored->generation, restored->evaluations);
        // in async mode the islands may stand at different generations: complete only when all are
        if (mpi.allTrue(ga.generation() >= s.ga.generations)) {
            if (root) log << "shapevo: " << folder << " is complete at generation " << ga.generation()
                          << "; pass --generations N to continue it\n";
            result.evaluations = ga.evaluations();
            return result;
        }
        // its figures until its next generation (async mode's statuses to rank 0)
        lastRow = islandRow(localCurve.empty() ? ga.stats() : localCurve.back(), ga.population().fitness);
    } else {
        ga.initialize(evaluator);
        stop = afterGeneration();
    }
    // Once each: incremental scoring's caches, and its models, have reached score.cache_mb.
    bool saidCacheFull = false, saidModelsFull = false;
    const auto sayBoundReached = [&](bool& said, bool reached, const char* what, const char* fromNowOn) {
        if (said || !reached) return;
        said = true;
        log << "shapevo: rank " << mpi.rank() << ": " << what << " score.cache_mb = " << s.incremental.cacheMb << " at generation "
            << ga.generation() << "; " << fromNowOn << " (results are the same; raise score.cache_mb for speed)\n";
    };
    while (!stop) {
        if (ga.generation() < s.ga.generations) {
            ga.step(evaluator);
            sayBoundReached(saidCacheFull, scene.scorer().cacheFull(), "incremental scoring has filled",
                            "the primitives it cannot keep, and models too large for it, are drawn the full way from now on");
            sayBoundReached(saidModelsFull, scene.scorer().modelsFull(), "the models kept for scoring children from their parents have reached",
                            "the largest are not kept from now on, and their children are scored from the caches");
            stop = afterGeneration();
        } else {  // async only: done with its generations, waiting for the others (the run's end)
            {
                WaitTimer wait(mpi);
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            stop = asyncTurn(true);
        }
    }
    control.finish();
    migration.finish();

    // The best individual of all islands goes to rank 0, which writes the outputs.
    const std::size_t bestIndex = ga.population().best();
    const auto [bestFitness, bestRank] = mpi.maxLoc(ga.population().fitness[bestIndex]);
    std::vector<std::uint32_t> packed;
    if (mpi.rank() == bestRank) {
        const Chromosome& c = ga.population().individuals[bestIndex];
        packed.push_back(c.genes);
        packed.insert(packed.end(), c.words.begin(), c.words.end());
    }
    packed = mpi.transfer(packed, bestRank, 0);
    const Scorer::Anomalies anomalies = scene.scorer().anomalies(), ofIoU = bestIoU.addedAnomalies();
    std::vector<double> totals{double(ga.evaluations()),
                               double(anomalies.nonFinite - anomaliesBefore.nonFinite - ofIoU.nonFinite),
                               double(anomalies.truncated - anomaliesBefore.truncated - ofIoU.truncated)};
    mpi.sum(totals);
    // waiting over the wall time: all of it, and the part outside checkpoints (async mode's promise)
    const double ownWait = waitShare(), ownWaitOutside = ownWait - checkpointWaited / std::max(1e-9, since(start));
    std::vector<double> overhead{migrationSeconds,
                                 checkpointSeconds,
                                 bestIoU.seconds(),
                                 ownWait,
                                 ownWaitOutside,
                                 double(evaluator.cacheBytesUsed()),
                                 double(scene.scorer().modelBytesInUse()),
                                 double(peakResidentBytes())};
    mpi.max(overhead);  // the slowest rank's share is what the run waited for; the largest rank's memory
    std::vector<double> waitSum{ownWait, ownWaitOutside};
    mpi.sum(waitSum);
    result.bestFitness = bestFitness;
    result.evaluations = std::uint64_t(totals[0]);
    result.wallSeconds = elapsed();
    result.stoppedBySignal = bySignal;
    if (root) {
        Chromosome champion;
        champion.genes = packed.front();
        champion.words.assign(packed.begin() + 1, packed.end());
        Geometry geometry;
        DeriveScratch scratch;
        derive(grammar, champion, geometry, scratch, s.limits.maxPrimitives);
        const Mesh mesh = meshOf(geometry);
        // best.png first: a grammar's texture named best.png then goes beside best.obj as best_2.png
        writeModelPicture(mesh, std::array{View::ThreeQuarter}, PictureSize{}, folder + "/best.png");
        writeObj(mesh, folder + "/best.obj");
        writePly(mesh, folder + "/best.ply");
        writeGlb(mesh, folder + "/best.glb");
        writeGenome(grammar, champion, folder + "/best.genome");
        writeCurveCsv(meta.curve, folder + "/curve.csv");
        CurvePlotLabels plot;
        plot.title = (s.name.empty() ? std::string("shapevo run") : s.name) + ": " + scene.description();
        plot.iouName = scene.kind().iouName;
        writeCurveSvg(meta.curve, plot, folder + "/curve.svg");
        writeCurvePng(meta.curve, plot, folder + "/curve.png");
        RunSummary sum;
        sum.name = s.name;
        sum.config = meta.configPath;
        sum.grammar = meta.grammarPath;
        sum.seed = s.seed;
        sum.generations = ga.generation();
        sum.evaluations = result.evaluations;
        sum.wallSeconds = result.wallSeconds;
        sum.bestFitness = result.bestFitness;
        sum.bestGenes = champion.genes;
        sum.bestPrimitives = geometry.primitives.size();
        sum.targetHash = scene.hash();
        scene.reportBest(champion, folder, sum);
        result.iou = sum.iou;
        sum.threads = evaluator.threads();
        sum.islands = mpi.size();
        sum.changedInputs = options.changedInputs;
        sum.nonFiniteModels = std::uint64_t(totals[1]);
        sum.truncatedModels = std::uint64_t(totals[2]);
        if (sum.nonFiniteModels > 0)
            std::cerr << "shapevo: warning: " << sum.nonFiniteModels << " evaluation(s) made a primitive with a non-finite "
                      << "coordinate or one beyond 1e6 and got the worst fitness (" << Scorer::kWorstFitness << ")\n";
        if (sum.truncatedModels > 0)
            std::cerr << "shapevo: warning: " << sum.truncatedModels << " evaluation(s) reached genome.max_primitives = "
                      << s.limits.maxPrimitives << " and were scored on their first " << s.limits.maxPrimitives
                      << " primitives\n";
        sum.migrationSeconds = overhead[0];
        sum.checkpointSeconds = overhead[1];
        sum.iouSeconds = overhead[2];
        sum.waitShareMax = overhead[3];
        sum.waitShareMean = waitSum[0] / islands;
        sum.waitShareOutsideCheckpointsMax = overhead[4];
        sum.waitShareOutsideCheckpointsMean = waitSum[1] / islands;
        sum.cacheBytes = std::uint64_t(overhead[5]);
        sum.modelBytes = std::uint64_t(overhead[6]);
        sum.maxRssBytes = std::uint64_t(overhead[7]);
        sum.population = ga.population().size();
        writeSummaryJson(sum, folder + "/summary.json");
        if (!options.quiet || result.stoppedBySignal) {
            char line[300];
            if (!bySignal)
                std::snprintf(line, sizeof line, "done%s%s: best fitness %.5f, %s %.4f, %llu evaluations in %s -> %s/\n",
                              stopReason == "done" ? "" : " after ", stopReason == "done" ? "" : stopReason.c_str(),
                              result.bestFitness, std::string(scene.kind().iouName).c_str(), result.iou, static_cast<unsigned long long>(result.evaluations),
                              humanSeconds(result.wallSeconds).c_str(), folder.c_str());
            else
                std::snprintf(line, sizeof line,
                              "stopped on %s after generation %u: checkpoint written; continue with: shapevo resume %s\n",
                              stopReason.c_str(), ga.generation(), folder.c_str());
            log << line;
        }
    }
    return result;
}

}  // namespace shapevo
