// shapevo command line: the commands of cli/commands.hpp (run, sample, target, translate,
// evaluate, resume, inspect, export, render, graph, reference), one file each in cli/commands/. Bad input
// (InputError, bad arguments, a wrong MPI set-up) prints one message and exits with code 2;
// other failures exit with code 1. Under mpirun every rank runs this; only the commands the
// table marks (run and resume) use more than one rank. Results go to stdout; errors, warnings
// and notices ("shapevo: ...") to stderr (cli/log_router.hpp). Output file names are checked
// (extension, existence), and a new run's memory estimate, before anything is read or created.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/input_error.hpp"
#include "base/keep_freed_memory.hpp"
#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/log_router.hpp"
#include "island/mpi_session.hpp"
#include "island/stop_signal.hpp"
#include "run/run_job.hpp"

int main(int argc, char** argv) {
    using namespace shapevo;
    keepFreedMemory();
    MpiSession mpi(argc, argv);
    const std::unique_ptr<CLI::App> parser = makeApp();
    CLI::App& app = *parser;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (mpi.rank() == 0) app.exit(e);
        return 2;
    }
    // Parse only: tests/cli/docs_commands_test.cpp checks that every command the docs show is one
    // shapevo accepts (its command, options and option values), without running the long ones.
    if (std::getenv("SHAPEVO_CHECK_ARGUMENTS")) return 0;
    const CommandEntry* command = nullptr;
    for (std::size_t i = 0; i < commands().size(); ++i)
        if (*app.get_subcommand(std::string(commands()[i].name))) command = &commands()[i];
    if (command->manyRanks) installStopSignalHandlers();  // early: a signal while loading must not kill a rank
    if (mpi.size() > 1 && !command->manyRanks) {
        if (mpi.rank() == 0)
            std::cerr << "shapevo: error: only " << manyRankCommandNames() << " use several MPI ranks; start '" << command->name
                      << "' without mpirun\n";
        return 2;
    }

    LogRouter router(std::cout, std::cerr);
    std::ostream log(&router);
    try {
        command->run(CommandContext{mpi, log});
    } catch (const SilentFailure&) {
        return 2;  // another rank's input was bad; that rank has said why
    } catch (const RunFailure& e) {  // a fault every rank saw (a checkpoint that cannot be written)
        if (!e.message.empty()) std::cerr << "shapevo: error: " << e.message << "\n";
        return 1;
    } catch (const InputError& e) {
        log.flush();
        std::cerr << "shapevo: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        log.flush();
        std::cerr << "shapevo: failed" << (mpi.size() > 1 ? " on rank " + std::to_string(mpi.rank()) : "") << ": "
                  << e.what() << "\n";
        if (mpi.size() > 1) mpi.abort(1);  // the other ranks would wait for this one forever
        return 1;
    }
    return 0;
}
