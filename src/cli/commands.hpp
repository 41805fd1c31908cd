// The commands of the shapevo binary: one table, one entry per command (its name, its one-line
// summary for --help, whether it may run on several MPI ranks, how it declares its options, how
// it runs). main.cpp adds every entry as a subcommand, in table order (the order --help lists),
// and runs the one the user named. A new command is its file in cli/commands/ (a struct like
// those below: its options, bound to storage the file owns, and its run) plus one entry in
// cli/commands.cpp.
#pragma once
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

#include "island/mpi_session.hpp"

namespace CLI {
class App;
}

namespace shapevo {

/// What a command runs with besides its own options.
struct CommandContext {
    const MpiSession& mpi;
    /// run and resume's log: results to stdout, "shapevo: ..." lines to stderr (cli/log_router.hpp).
    std::ostream& log;
};

struct CommandEntry {
    std::string_view name;     ///< the subcommand: shapevo NAME ...
    std::string_view summary;  ///< its description in --help
    bool manyRanks;            ///< may run on several MPI ranks (under mpirun); the others refuse to
    /// Declares the command's options and positionals on its subcommand `command`.
    void (*addOptions)(CLI::App& command);
    /// Runs the command with the options parsed. Results go to stdout, diagnostics to stderr.
    /// @throw InputError for bad input (exit 2); SilentFailure, RunFailure (run_job.hpp).
    void (*run)(const CommandContext& context);
};

/// Every command, in the order --help lists them.
std::span<const CommandEntry> commands();

/// The commands that may run on several ranks, for a message: "'run' and 'resume'".
std::string manyRankCommandNames();

// One struct per command, defined in cli/commands/<name>.cpp.
struct RunCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct SampleCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct TargetCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct TranslateCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct EvaluateCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct ResumeCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct InspectCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct ExportCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct RenderCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct GraphCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };
struct ReferenceCommand { static void addOptions(CLI::App& command); static void run(const CommandContext& context); };

/// What inspect and export accept for a checkpoint (checkpoint/checkpoint_path.hpp).
inline constexpr const char* kCheckpointPaths =
    "a run folder (its newest complete checkpoint), a checkpoint folder (checkpoint-NNNNNN), or a checkpoint's "
    "run.h5 or island-NNNN.h5 (the checkpoint that holds it)";

}  // namespace shapevo
