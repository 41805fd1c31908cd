// Stop signals: SIGTERM and SIGUSR1 (what Slurm sends before the wall-time limit), SIGINT (Ctrl-C)
// and SIGHUP (a closed terminal) ask the run to finish its generation, write a checkpoint and
// exit 0. The handler only sets a flag, and stays installed, so a second signal changes nothing.
#pragma once

namespace shapevo {

/// Install the handlers (idempotent).
void installStopSignalHandlers();
/// The signal number received so far, or 0.
int stopSignalReceived();
/// "SIGTERM", "SIGUSR1", ...
const char* signalName(int signal);

}  // namespace shapevo
