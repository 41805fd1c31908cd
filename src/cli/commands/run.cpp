// `shapevo run CONFIG.toml`: a new run (run/run_job.hpp), on one rank or on every rank mpirun starts.
// Its config, overrides (--set, then --seed, which wins), threads and output folder are checked,
// and the run's memory estimate on this machine, before anything is created.
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "base/input_error.hpp"
#include "run/models/loaded_model.hpp"
#include "search/search_methods.hpp"
#include "run/command_options.hpp"
#include "run/config_file.hpp"
#include "island/together.hpp"
#include "run/memory_check.hpp"
#include "run/run_job.hpp"
#include "search/evaluator.hpp"

namespace shapevo {

namespace {

struct RunOptions {
    std::string config;
    std::string seed;
    CLI::Option* seedOption = nullptr;  ///< whether --seed was given
    std::vector<std::string> sets;
    std::string out;
    bool quiet = false;
    int threads = -1;
};
RunOptions runOptions;

/// MPI ranks on this machine, from the launcher's environment (Open MPI, MPICH, Slurm); 1 if unknown.
int ranksOnThisMachine() {
    for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "SLURM_NTASKS_PER_NODE"})
        if (const char* v = std::getenv(name)) {
            const int n = std::atoi(v);
            if (n > 0) return n;
        }
    return 1;
}

}  // namespace

void RunCommand::addOptions(CLI::App& command) {
    RunOptions& o = runOptions;
    command.add_option("config", o.config, "TOML config (see configs/)")->required();
    o.seedOption = command.add_option("--seed", o.seed, "random seed, 0 to 2^63-1 (overrides run.seed; written into the run's config.toml)");
    command.add_option("--set", o.sets,
                       "override a config value, e.g. --set ga.population=50 (repeatable); --set run.wall_time=60 "
                       "without ga.generations runs for 60 s, with it for whichever comes first");
    command.add_option("--out", o.out, "output folder; must not exist (default runs/<name>, runs/<name>-2, ...)");
    command.add_option("--threads", o.threads, "threads (overrides run.threads; 0 = all cores)")->check(CLI::NonNegativeNumber);
    command.add_flag("-q,--quiet", o.quiet, "no per-generation progress lines");
}

void RunCommand::run(const CommandContext& context) {
    const RunOptions& o = runOptions;
    const MpiSession& mpi = context.mpi;
    // --seed is an override like --set, after them (it wins), so the config text the run
    // stores (config.toml, checkpoints) holds the seed it ran with.
    std::vector<std::string> sets = o.sets;
    if (*o.seedOption) sets.push_back("run.seed=" + std::to_string(parseSeed(o.seed, "--seed", INT64_MAX)));
    RunSettings s = loadConfig(o.config, sets);
    if (o.threads >= 0) s.threads = o.threads;
    if (!o.out.empty()) s.out = o.out;
    if (const int used = Evaluator::usableThreads(s.threads); s.threads > used && mpi.rank() == 0)
        std::cerr << "shapevo: warning: " << (o.threads >= 0 ? "--threads " : "run.threads = ") << s.threads
                  << " is more than the " << used << " hardware thread(s) this process may use; using " << used << "\n";
    together(mpi, [&] {
        const std::unique_ptr<LoadedModel> model = LoadedModel::load(s);
        if (const std::string problem = methodFamilyProblem(s.search, model->family()); !problem.empty())
            throw InputError(s.configPath, "search.method", problem);
        requireMemoryFits(s, model->family(), ranksOnThisMachine(), usableMemoryBytes());
    });
    JobOptions job;
    job.quiet = o.quiet;
    runJob(mpi, s, job, context.log);
}

}  // namespace shapevo
