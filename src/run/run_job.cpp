// run / resume: set-up that every rank agrees on, then the island loop (island_loop.cpp).
#include "run/run_job.hpp"

#include <filesystem>
#include <ostream>
#include <sstream>

#include "base/atomic_write.hpp"
#include "base/side_by_side.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "genome/families/tree_family.hpp"
#include "grammar/front_ends.hpp"
#include "run/config_file.hpp"
#include "base/input_error.hpp"
#include "run/island_loop.hpp"
#include "checkpoint/run_identity.hpp"
#include "run/output_folder.hpp"
#include "run/run_folder_lock.hpp"
#include "run/run_limit.hpp"

namespace shapevo {

namespace {

void writeFile(const std::string& path, const std::string& text) {
    writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
}

/// Every input file of a run: the config, the grammar, the files it includes, the meshes and
/// textures it names and the targets (with the hashes of the bytes the scene read, where its kind
/// kept them: a target is read once).
std::vector<InputFile> inputsOf(const RunSettings& s, const LoadedModel& model, const Scene& scene) {
    std::vector<InputFile> inputs{hashInput("config", s.configPath), hashInput("grammar", s.grammarPath)};
    for (const auto& [role, path] : model.extraInputs(s.grammarPath)) inputs.push_back(hashInput(role, path));
    const std::vector<std::string> targets = s.target->inputFiles();
    const std::vector<std::uint64_t>& read = scene.targetInputHashes();
    for (std::size_t i = 0; i < targets.size(); ++i)
        inputs.push_back(read.size() == targets.size() ? recordInput("target", targets[i], read[i])
                                                       : hashInput("target", targets[i]));
    return inputs;
}

}  // namespace

JobResult runJob(const MpiSession& mpi, const RunSettings& s, const JobOptions& options, std::ostream& log) {
    // Read every input before creating anything, so bad input leaves no trace.
    std::unique_ptr<LoadedModel> model;
    std::unique_ptr<Scene> scene;
    RunMetadata meta;
    together(mpi, [&] {
        model = LoadedModel::load(s);
        scene = Scene::load(s, *model);
        if (mpi.rank() == 0) meta.inputs = inputsOf(s, *model, *scene);
    });
    std::string folder;
    RunFolderLock lock;
    together(mpi, [&] {
        if (mpi.rank() != 0) return;
        folder = claimOutputFolder(s.out, s.name);
        lock = RunFolderLock(folder);
    });
    folder = mpi.broadcast(folder);
    meta.runId = mpi.broadcast(mpi.rank() == 0 ? newRunId() : std::string());
    if (mpi.rank() == 0)  // side by side: each waits for the disk (base/side_by_side.hpp)
        runSideBySide({[&] { writeRunId(folder, meta.runId); },
                       [&] { writeFile(folder + "/config.toml", s.configText); },
                       [&] { writeFile(folder + "/" + std::filesystem::path(s.grammarPath).filename().string(), model->source()); }});
    meta.seed = s.seed;
    meta.ranks = mpi.size();
    meta.targetHash = scene->hash();
    meta.name = s.name;
    meta.configPath = std::filesystem::absolute(s.configPath).lexically_normal().string();
    meta.configText = s.configText;
    meta.grammarPath = std::filesystem::absolute(s.grammarPath).lexically_normal().string();
    meta.grammarText = model->source();
    return islandLoop(mpi, s, *model, *scene, folder, meta, nullptr, options, log);
}

namespace {

/// How many island files `checkpoint`'s MANIFEST lists (0 if it cannot be read).
int listedIslands(const std::string& checkpoint) {
    int n = 0;
    try {
        for (const ManifestEntry& e : readManifest(checkpoint)) n += e.name.rfind("island-", 0) == 0;
    } catch (const InputError&) {
        return 0;
    }
    return n;
}

}  // namespace

JobResult resumeJob(const MpiSession& mpi, const std::string& runDir, const JobOptions& options, std::ostream& log) {
    // Rank 0 locks the folder and lists the checkpoints; all ranks walk the list together, newest
    // first, and take the first that is this run's, complete on disk and readable on every rank.
    // Every skip is decided collectively (allTrue / fromRoot), so no rank can go on alone.
    std::string listing, runId;
    RunFolderLock lock;
    together(mpi, [&] {
        if (mpi.rank() != 0) return;
        if (!std::filesystem::is_directory(runDir)) throw InputError(runDir, "", "not a run folder");
        lock = RunFolderLock(runDir);
        runId = readRunId(runDir);
        for (const auto& c : listCheckpoints(runDir)) listing += c + "\n";
        if (listing.empty()) throw InputError(runDir, "", "holds no checkpoint to resume from");
    });
    listing = mpi.broadcast(listing);
    runId = mpi.broadcast(runId);
    std::istringstream names(listing);
    std::string candidate;
    auto skip = [&](const std::string& why) {
        if (mpi.rank() == 0) log << "shapevo: checkpoint " << candidate << " " << why << "; trying the one before it\n";
    };
    while (std::getline(names, candidate)) {
        std::string problem = mpi.rank() == 0 ? verifyCheckpoint(candidate) : "";
        if (!mpi.fromRoot(problem.empty())) {
            skip("is incomplete or damaged (" + problem + ")");
            continue;
        }
        RunMetadata meta;
        try {
            meta = readRunMetadata(candidate + "/run.h5");
        } catch (const InputError& e) {
            problem = e.what();
        }
        if (!mpi.allTrue(problem.empty())) {
            if (!problem.empty()) log << "shapevo: rank " << mpi.rank() << ": " << problem << "\n";
            skip("cannot be read");
            continue;
        }
        if (!mpi.allTrue(meta.runId == runId)) {  // agreed, even if a rank's file system showed another run.h5
            skip("belongs to another run (run id " + meta.runId + ", seed " + std::to_string(meta.seed) +
                 "), not to this folder's run " + runId + "; it is left untouched");
            continue;
        }
        const int listed = mpi.rank() == 0 ? listedIslands(candidate) : 0;
        if (!mpi.fromRoot(listed == meta.ranks)) {
            skip("is damaged (its MANIFEST lists " + std::to_string(listed) + " island files, run.h5 says " +
                 std::to_string(meta.ranks) + ")");
            continue;
        }
        RunSettings s;
        std::unique_ptr<LoadedModel> model;
        std::unique_ptr<Scene> scene;
        std::vector<std::string> changed;
        together(mpi, [&] {
            if (meta.ranks != mpi.size())
                throw InputError(candidate, "", "this checkpoint holds " + std::to_string(meta.ranks) + " island(s) but " +
                                                    std::to_string(mpi.size()) + " rank(s) were started; resume with mpirun -np " +
                                                    std::to_string(meta.ranks));
            changed = changedInputs(meta.inputs);
            if (!changed.empty() && !options.allowChangedInputs)
                throw InputError(runDir, "", "an input changed since the run started: " + changed.front() +
                                                 (changed.size() > 1 ? " (and " + std::to_string(changed.size() - 1) + " more)" : "") +
                                                 "; resume with --allow-changed-inputs to continue with the files as they are now");
            s = parseConfig(meta.configText, meta.configPath);
            s.seed = meta.seed;
            if (options.generations) s.population.generations = *options.generations, s.generationsGiven = true;
            if (options.wallTime) s.wallTime = *options.wallTime;
            settleRunLimit(s);
            model = LoadedModel::fromText(s, meta.grammarText, meta.grammarPath);
            scene = Scene::load(s, *model);
            if (scene->hash() != meta.targetHash && !options.allowChangedInputs)
                throw InputError(scene->primaryFile(), "", "the target changed since the run started (hash differs); "
                                                             "resuming against another target is refused");
        });
        const GenomeFamily& family = model->family();
        IslandState state;
        std::string readProblem;
        try {
            state = readIslandFile(candidate + "/" + islandFileName(mpi.rank()), family, s.limits);
            readProblem = islandMismatch(state, meta, mpi.rank(), s.migration.async && meta.ranks > 1);
            if (!readProblem.empty()) readProblem = islandFileName(mpi.rank()) + ": " + readProblem;
        } catch (const InputError& e) {
            readProblem = e.what();
        }
        if (!mpi.allTrue(readProblem.empty())) {
            if (!readProblem.empty()) log << "shapevo: rank " << mpi.rank() << ": " << readProblem << "\n";
            skip("cannot be read");
            continue;
        }
        if (mpi.rank() == 0) {
            for (const std::string& c : changed) log << "shapevo: warning: " << c << " (accepted: --allow-changed-inputs)\n";
            if (!options.quiet)
                log << "resuming " << runDir << " from " << candidate << " (generation " << meta.generation << ")\n";
        }
        JobOptions withChanges = options;
        withChanges.changedInputs = changed;
        return islandLoop(mpi, s, *model, *scene, runDir, meta, &state, withChanges, log);
    }
    together(mpi, [&] {
        if (mpi.rank() == 0) throw InputError(runDir, "", "no complete checkpoint of this run to resume from");
    });
    throw SilentFailure{};
}

}  // namespace shapevo
