// run / resume: set-up that every rank agrees on, then the island loop (island_loop.cpp).
#include "run/run_job.hpp"

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "base/atomic_write.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "grammar/parser.hpp"
#include "run/config_file.hpp"
#include "base/input_error.hpp"
#include "run/island_loop.hpp"
#include "run/output_folder.hpp"

namespace shapevo {

namespace {

/// Every individual starts with the start rule's mandatory subtree; it must fit the length limit.
void requireRootFits(const RunSettings& s, const Grammar& g) {
    if (g.mandatoryGenes[g.start] > s.limits.maxGenes)
        throw InputError(s.configPath, "[genome] max_genes",
                         std::to_string(s.limits.maxGenes) + " is smaller than the " + std::to_string(g.mandatoryGenes[g.start]) +
                             " genes every derivation of " + g.path + " needs");
}

void writeFile(const std::string& path, const std::string& text) {
    writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace

JobResult runJob(const MpiSession& mpi, const RunSettings& s, const JobOptions& options, std::ostream& log) {
    // Read every input before creating anything, so bad input leaves no trace.
    Grammar grammar;
    std::unique_ptr<Scene> scene;
    together(mpi, [&] {
        grammar = loadGrammar(s.grammarPath);
        requireRootFits(s, grammar);
        scene = Scene::load(s, grammar);
    });
    std::string folder;
    together(mpi, [&] {
        if (mpi.rank() == 0) folder = claimOutputFolder(s.out, s.name);
    });
    folder = mpi.broadcast(folder);
    if (mpi.rank() == 0) {
        writeFile(folder + "/config.toml", s.configText);
        writeFile(folder + "/" + std::filesystem::path(s.grammarPath).filename().string(), grammar.source);
    }
    RunMetadata meta;
    meta.seed = s.seed;
    meta.ranks = mpi.size();
    meta.targetHash = scene->hash();
    meta.name = s.name;
    meta.configPath = std::filesystem::absolute(s.configPath).lexically_normal().string();
    meta.configText = s.configText;
    meta.grammarPath = std::filesystem::absolute(s.grammarPath).lexically_normal().string();
    meta.grammarText = grammar.source;
    return islandLoop(mpi, s, grammar, *scene, folder, meta, nullptr, options, log);
}

JobResult resumeJob(const MpiSession& mpi, const std::string& runDir, const JobOptions& options, std::ostream& log) {
    // Rank 0 lists the checkpoints; all ranks walk the list together, newest first, and take the
    // first that is complete on disk and readable on every rank.
    std::string listing;
    together(mpi, [&] {
        if (mpi.rank() != 0) return;
        if (!std::filesystem::is_directory(runDir)) throw InputError(runDir, "", "not a run folder");
        for (const auto& c : listCheckpoints(runDir)) listing += c + "\n";
        if (listing.empty()) throw InputError(runDir, "", "holds no checkpoint to resume from");
    });
    listing = mpi.broadcast(listing);
    std::istringstream names(listing);
    std::string candidate;
    while (std::getline(names, candidate)) {
        std::string problem = mpi.rank() == 0 ? verifyCheckpoint(candidate) : "";
        if (!mpi.fromRoot(problem.empty())) {
            if (mpi.rank() == 0) log << "shapevo: checkpoint " << candidate << " is incomplete or damaged (" << problem
                                    << "); trying the one before it\n";
            continue;
        }
        RunMetadata meta;
        RunSettings s;
        Grammar grammar;
        std::unique_ptr<Scene> scene;
        together(mpi, [&] {
            meta = readRunMetadata(candidate + "/run.h5");
            if (meta.ranks != mpi.size())
                throw InputError(candidate, "", "this checkpoint holds " + std::to_string(meta.ranks) + " island(s) but " +
                                                    std::to_string(mpi.size()) + " rank(s) were started; resume with mpirun -np " +
                                                    std::to_string(meta.ranks));
            s = parseConfig(meta.configText, meta.configPath);
            if (options.generations) s.ga.generations = *options.generations;
            grammar = parseGrammar(meta.grammarText, meta.grammarPath);
            requireRootFits(s, grammar);
            scene = Scene::load(s, grammar);
            if (scene->hash() != meta.targetHash)
                throw InputError(scene->primaryFile(), "", "the target changed since the run started (hash differs); "
                                                             "resuming against another target is refused");
        });
        IslandState state;
        std::string readProblem;
        try {
            state = readIslandFile(candidate + "/" + islandFileName(mpi.rank()), grammar, s.limits);
        } catch (const InputError& e) {
            readProblem = e.what();
        }
        if (!mpi.allTrue(readProblem.empty())) {
            if (!readProblem.empty()) log << "shapevo: rank " << mpi.rank() << ": " << readProblem << "\n";
            if (mpi.rank() == 0) log << "shapevo: checkpoint " << candidate << " cannot be read; trying the one before it\n";
            continue;
        }
        if (mpi.rank() == 0 && !options.quiet)
            log << "resuming " << runDir << " from " << candidate << " (generation " << meta.generation << ")\n";
        return islandLoop(mpi, s, grammar, *scene, runDir, meta, &state, options, log);
    }
    together(mpi, [&] {
        if (mpi.rank() == 0) throw InputError(runDir, "", "no complete checkpoint to resume from");
    });
    throw SilentFailure{};
}

}  // namespace shapevo
