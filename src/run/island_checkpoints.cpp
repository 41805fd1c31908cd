// IslandCheckpoints: the collective write (partial folder, agreement, one rename) and its timing.
#include "run/island_checkpoints.hpp"

#include <filesystem>
#include <ostream>

#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/run_identity.hpp"
#include "run/job_options.hpp"

namespace shapevo {

namespace {

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

/// What a user needs after a failed checkpoint: the newest complete checkpoint of this run.
std::string newestCompleteCheckpoint(const std::string& folder, const std::string& runId) {
    for (const std::string& c : listCheckpoints(folder))
        if (verifyCheckpoint(c).empty() && checkpointRunId(c) == runId) return "the newest complete checkpoint is " + c + "; resume from it once fixed";
    return "there is no complete checkpoint of this run yet";
}

}  // namespace

IslandCheckpoints::IslandCheckpoints(const MpiSession& mpi, const CheckpointSettings& settings, const std::string& folder,
                                     std::ostream& log)
    : mpi_(mpi), settings_(settings), folder_(folder), log_(log), last_(LoopClock::Clock::now()) {}

bool IslandCheckpoints::dueByCount(std::uint32_t generation) const {
    return settings_.interval > 0 && generation % settings_.interval == 0;
}

bool IslandCheckpoints::dueByTime() const {
    return mpi_.rank() == 0 && settings_.seconds > 0 && LoopClock::since(last_) >= settings_.seconds;
}

void IslandCheckpoints::write(const std::function<IslandState()>& islandNow, const RunMetadata& meta) {
    const auto start = LoopClock::Clock::now();
    const double waitedBefore = mpi_.waitedSeconds();
    const IslandState island = islandNow();
    const std::string failed = writeCheckpoint(mpi_, folder_, island, meta, settings_.keep, log_);
    if (!failed.empty())  // every rank sees the failure: stop now rather than lose more work
        throw RunFailure{mpi_.rank() == 0 ? "checkpoint at generation " + std::to_string(meta.generation) +
                                                " could not be written: " + failed + "; the run stops; " +
                                                newestCompleteCheckpoint(folder_, meta.runId)
                                          : std::string()};
    seconds_ += LoopClock::since(start);
    waitedSeconds_ += mpi_.waitedSeconds() - waitedBefore;
    last_ = LoopClock::Clock::now();
}

}  // namespace shapevo
