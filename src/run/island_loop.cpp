// islandLoop: one island from its first (or restored) generation to the end-of-run outputs.
// IslandLoop owns the island's search, its migration, its own curve and its timing, and calls the
// parts in order: after each generation its own figures, then the turn of its migration mode
// (run/sync_turns.hpp: the islands meet; run/async_turns.hpp: rank 0 hears statuses and gives
// orders without anyone waiting), a checkpoint when the turn asks for one
// (run/island_checkpoints.hpp), and at the end the outputs (run/run_outputs.hpp).
#include "run/island_loop.hpp"

#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "base/format_double.hpp"
#include "base/peak_memory.hpp"
#include "island/ring_migration.hpp"
#include "island/stop_signal.hpp"
#include "run/async_turns.hpp"
#include "run/best_model_iou.hpp"
#include "run/diagnostics_log.hpp"
#include "run/island_checkpoints.hpp"
#include "run/loop_clock.hpp"
#include "run/progress_line.hpp"
#include "run/run_limit.hpp"
#include "run/run_outputs.hpp"
#include "run/sync_turns.hpp"
#include "search/evaluator.hpp"
#include "search/search_methods.hpp"

namespace shapevo {

namespace {

/// Island r's seed: r = 0 keeps the run's seed, so a one-rank MPI run equals a plain run.
std::uint64_t islandSeed(std::uint64_t seed, int rank) { return seed + 0x9e3779b97f4a7c15ULL * std::uint64_t(rank); }

class IslandLoop {
public:
    IslandLoop(const MpiSession& mpi, const RunSettings& s, const LoadedModel& model, const Scene& scene, const std::string& folder, RunMetadata meta, const IslandState* restored,
               const JobOptions& options, std::ostream& log);
    IslandLoop(const IslandLoop&) = delete;
    IslandLoop& operator=(const IslandLoop&) = delete;

    JobResult run();

private:
    void printStartLine();
    /// Every rank's own part of a generation: migration, its figures, its own curve row.
    void ownGeneration();
    /// After a generation: its own part, then its mode's turn; whether the run stops.
    bool afterGeneration();
    /// Write the checkpoint the turn asked for (collective); whether the run stops.
    bool follow(TurnDecision decision);
    /// This rank's island as a checkpoint stores it (collective in sync mode: migrants in flight).
    IslandState islandNow();
    /// Once each: incremental scoring's caches, and its models, have reached score.cache_mb.
    void sayBoundsReached();
    /// The best individual and the totals from every rank; rank 0 writes the outputs.
    JobResult end(JobResult result);

    const MpiSession& mpi_;
    const RunSettings& s_;
    const LoadedModel& model_;
    const GenomeFamily& family_;
    const Scene& scene_;
    const std::string& folder_;
    RunMetadata meta_;  ///< the run's curve, generation and time: what rank 0 checkpoints and reports
    const IslandState* restored_;
    const JobOptions& options_;
    std::ostream& log_;

    LoopClock clock_;
    const bool root_;
    Evaluator evaluator_;
    const Scorer::Anomalies anomaliesBefore_;  // the start-up checks' models do not count
    const std::unique_ptr<SearchMethod> method_;
    SearchMethod& search_;
    RingMigration migration_;
    std::vector<GenerationStats> localCurve_;  ///< this island's own rows
    BestModelIoU bestIoU_;
    std::optional<DiagnosticsLog> diagnostics_;  // search.diagnostics: rank 0's island, a row per generation
    IslandCheckpoints checkpoints_;
    ProgressLine progress_;
    const int islands_;
    StopReason stop_;
    double migrationSeconds_ = 0;  // this rank's time in migration, for the summary
    IslandRow lastRow_;            ///< this island's figures of its newest generation
    SyncTurns syncTurns_;
    AsyncTurns asyncTurns_;        // its finish() is collective in either mode
    const bool async_;
    bool saidCacheFull_ = false, saidModelsFull_ = false;
};

IslandLoop::IslandLoop(const MpiSession& mpi, const RunSettings& s, const LoadedModel& model, const Scene& scene, const std::string& folder, RunMetadata meta, const IslandState* restored,
                       const JobOptions& options, std::ostream& log)
    : mpi_(mpi), s_(s), model_(model), family_(model.family()), scene_(scene), folder_(folder), meta_(std::move(meta)), restored_(restored),
      options_(options), log_(log), clock_(mpi, meta_.wallSeconds), root_(mpi.rank() == 0),
      evaluator_(scene.scorer(), s.threads), anomaliesBefore_(scene.scorer().anomalies()),
      method_(makeSearchMethod(s.search, s.population, s.ga, family_, s.limits, islandSeed(s.seed, mpi.rank()), s.configPath)),
      search_(*method_), migration_(mpi, s.migration, family_, s.limits),
      localCurve_(restored ? restored->curve : std::vector<GenerationStats>{}),
      checkpoints_(mpi, s.checkpoint, folder, log), progress_(log, s.population.generations, s.wallTime),
      islands_(mpi.active() ? mpi.size() : 1),
      syncTurns_(TurnContext{mpi, s, clock_, checkpoints_, root_ && !options.quiet ? &progress_ : nullptr, islands_, meta_, stop_}),
      asyncTurns_(TurnContext{mpi, s, clock_, checkpoints_, root_ && !options.quiet ? &progress_ : nullptr, islands_, meta_, stop_}),
      async_(s.migration.async && islands_ > 1) {
    if (restored) migration_.restoreArrivals(restored->arrivals);
    installStopSignalHandlers();
    if (root_ && s.search.diagnostics) diagnostics_.emplace(folder + "/diagnostics.csv", family_);
}

void IslandLoop::printStartLine() {
    if (root_ && !options_.quiet)
        log_ << "shapevo " << (restored_ ? "resume " : "run ") << s_.name << ": grammar " << s_.grammarPath << ", target "
             << scene_.description() << (scene_.choices().empty() ? "" : ", ") << scene_.choices() << ", " << mpi_.size()
             << " island(s) x " << evaluator_.threads() << " thread(s), seed " << s_.seed << ", output " << folder_ << ", "
             << runLimitText(s_) << "\n";
}

void IslandLoop::ownGeneration() {
    const auto migrationStart = LoopClock::Clock::now();
    migration_.afterGeneration(search_.population(), search_.generation(), search_.migrantSlots());
    migrationSeconds_ += LoopClock::since(migrationStart);
    GenerationStats local = search_.stats();
    local.seconds = clock_.runSeconds();
    local.iou = bestIoU_.of(scene_, search_.population().individuals[search_.population().best()]);
    localCurve_.push_back(local);
    lastRow_ = islandRow(local, search_.population().fitness);
    if (diagnostics_) diagnostics_->write(search_, local.seconds);
}

bool IslandLoop::afterGeneration() {
    ownGeneration();
    return follow(async_ ? asyncTurns_.after(lastRow_, search_.generation(), search_.evaluations())
                         : syncTurns_.after(lastRow_, search_.generation()));
}

bool IslandLoop::follow(TurnDecision decision) {
    if (decision.checkpoint) checkpoints_.write([&] { return islandNow(); }, meta_);
    return decision.stop;
}

IslandState IslandLoop::islandNow() {
    IslandState island;
    island.runId = meta_.runId;
    island.seed = meta_.seed;
    island.ranks = meta_.ranks;
    island.rank = mpi_.rank();
    island.generation = search_.generation();
    island.evaluations = search_.evaluations();
    island.rng = search_.rng().state();
    island.population = search_.population();
    island.arrivals = migration_.arrivals();  // sync: receives what is still in flight to this rank
    island.curve = localCurve_;
    return island;
}

void IslandLoop::sayBoundsReached() {
    const auto say = [&](bool& said, bool reached, const char* what, const char* fromNowOn) {
        if (said || !reached) return;
        said = true;
        log_ << "shapevo: rank " << mpi_.rank() << ": " << what << " score.cache_mb = " << s_.incremental.cacheMb
             << " at generation " << search_.generation() << "; " << fromNowOn
             << " (results are the same; raise score.cache_mb for speed)\n";
    };
    say(saidCacheFull_, scene_.scorer().cacheFull(), "incremental scoring has filled",
        "the primitives it cannot keep, and models too large for it, are drawn the full way from now on");
    say(saidModelsFull_, scene_.scorer().modelsFull(), "the models kept for scoring children from their parents have reached",
        "the largest are not kept from now on, and their children are scored from the caches");
}

JobResult IslandLoop::run() {
    printStartLine();
    JobResult result;
    result.folder = folder_;
    bool stop = false;
    if (restored_) {
        search_.restore(restored_->population, restored_->rng, restored_->generation, restored_->evaluations);
        // in async mode the islands may stand at different generations: complete only when all are;
        // a run whose wall time is spent (the same run.h5 time on every rank) is complete too
        const bool timeSpent = s_.wallTime > 0 && clock_.secondsBefore() >= s_.wallTime;
        if (mpi_.allTrue(search_.generation() >= s_.population.generations) || timeSpent) {
            if (root_)
                log_ << "shapevo: " << folder_ << " is complete at generation " << search_.generation()
                     << (timeSpent ? "; its wall time (" + formatDouble(s_.wallTime) + " s) is spent: pass --wall-time S to continue it\n"
                                   : "; pass --generations N to continue it\n");
            result.evaluations = search_.evaluations();
            return result;
        }
    } else {
        search_.initialize(evaluator_);
        stop = afterGeneration();
    }
    // Sync mode stops every island after the same generation. In async mode an island that has
    // done its generations goes on evolving until rank 0 orders the stop (once every island has
    // done them), so no island waits for the slowest at the end of the run.
    while (!stop) {
        search_.step(evaluator_);
        sayBoundsReached();
        stop = afterGeneration();
    }
    asyncTurns_.finish();
    migration_.finish();
    return end(std::move(result));
}

JobResult IslandLoop::end(JobResult result) {
    // The best individual of all islands goes to rank 0, which writes the outputs.
    Champion champion = gatherChampion(mpi_, search_.population());
    const Scorer::Anomalies anomalies = scene_.scorer().anomalies(), ofIoU = bestIoU_.addedAnomalies();
    IslandTotals own;
    own.evaluations = search_.evaluations();
    own.anomalies.nonFinite = anomalies.nonFinite - anomaliesBefore_.nonFinite - ofIoU.nonFinite;
    own.anomalies.truncated = anomalies.truncated - anomaliesBefore_.truncated - ofIoU.truncated;
    own.migrationSeconds = migrationSeconds_;
    own.checkpointSeconds = checkpoints_.seconds();
    own.iouSeconds = bestIoU_.seconds();
    own.checkpointWaitedSeconds = checkpoints_.waitedSeconds();
    own.cacheBytes = evaluator_.cacheBytesUsed();
    own.modelBytes = scene_.scorer().modelBytesInUse();
    own.peakResidentBytes = peakResidentBytes();
    const RunTotals totals = gatherTotals(mpi_, own, clock_);
    result.bestFitness = champion.fitness;
    result.evaluations = totals.evaluations;
    result.wallSeconds = clock_.runSeconds();
    result.stoppedBySignal = stop_.bySignal;
    if (root_) {
        RunEnd outputs{s_, model_, scene_, folder_, meta_, options_, std::move(champion.chromosome), totals,
                       search_.generation(), search_.population().size(), evaluator_.threads(), islands_, mpi_.size(), stop_};
        writeRunOutputs(outputs, result, log_);
    }
    return result;
}

}  // namespace

JobResult islandLoop(const MpiSession& mpi, const RunSettings& s, const LoadedModel& model, const Scene& scene,
                     const std::string& folder, RunMetadata meta, const IslandState* restored, const JobOptions& options,
                     std::ostream& log) {
    IslandLoop loop(mpi, s, model, scene, folder, std::move(meta), restored, options, log);
    return loop.run();
}

}  // namespace shapevo
