// Stop signals: SIGTERM and SIGUSR1 (what Slurm sends before the wall-time limit), SIGINT (Ctrl-C)
// and SIGHUP (a closed terminal) ask the run to finish its generation, write a checkpoint and
// exit 0. The handler only sets a flag, and stays installed, so a second signal changes nothing.
// The same path serves a rank that lost its launcher (island/launcher_watch.hpp): requestStop
// with kLauncherLost, a number no signal has.
#pragma once

namespace shapevo {

/// The stop "signal" of a rank whose launcher (mpirun, srun) is gone: above every signal number.
inline constexpr int kLauncherLost = 65;

/// Install the handlers (idempotent).
void installStopSignalHandlers();
/// Ask for a stop as if `signal` had arrived (callable from any thread or a signal handler).
void requestStop(int signal);
/// The signal number received so far (or requested), or 0.
int stopSignalReceived();
/// "SIGTERM", "SIGUSR1", ..., "the loss of its launcher (mpirun or srun)"
const char* signalName(int signal);

}  // namespace shapevo
