// `shapevo resume RUN_DIR`: continue a run from its newest complete checkpoint (run/run_job.hpp),
// on one rank or on every rank mpirun starts; --generations and --wall-time give it new limits
// (run/run_limit.hpp: the same rules as ga.generations and run.wall_time).
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "run/run_job.hpp"

namespace shapevo {

namespace {

struct ResumeOptions {
    std::string runDir;
    std::uint32_t generations = 0;
    CLI::Option* generationsOption = nullptr;  ///< whether --generations was given
    double wallTime = 0;
    CLI::Option* wallTimeOption = nullptr;     ///< whether --wall-time was given
    bool quiet = false;
    bool allowChangedInputs = false;
};
ResumeOptions resumeOptions;

}  // namespace

void ResumeCommand::addOptions(CLI::App& command) {
    ResumeOptions& o = resumeOptions;
    command.add_option("run_dir", o.runDir, "the run folder")->required();
    o.generationsOption = command.add_option("--generations", o.generations,
                                             "new generation limit, as ga.generations (extends a finished run)");
    o.wallTimeOption = command.add_option("--wall-time", o.wallTime,
                                          "new wall time of the whole run in seconds, as run.wall_time (extends a run that "
                                          "stopped at its wall time)")
                           ->check(CLI::Range(0.001, 1e9));
    command.add_flag("-q,--quiet", o.quiet, "no per-generation progress lines");
    command.add_flag("--allow-changed-inputs", o.allowChangedInputs,
                    "continue although an input file (config, grammar, mesh, target) changed since the run "
                    "started; the change is recorded in summary.json");
}

void ResumeCommand::run(const CommandContext& context) {
    const ResumeOptions& o = resumeOptions;
    JobOptions job;
    job.quiet = o.quiet;
    if (*o.generationsOption) job.generations = o.generations;
    if (*o.wallTimeOption) job.wallTime = o.wallTime;
    job.allowChangedInputs = o.allowChangedInputs;
    resumeJob(context.mpi, o.runDir, job, context.log);
}

}  // namespace shapevo
