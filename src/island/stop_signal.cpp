// Stop signals: an async-signal-safe flag set by the handler, read once per generation.
#include "island/stop_signal.hpp"

#include <csignal>
#include <initializer_list>

namespace shapevo {

namespace {
volatile std::sig_atomic_t gSignal = 0;
extern "C" void onStopSignal(int s) { gSignal = s; }
}  // namespace

void installStopSignalHandlers() {
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    // The handler stays installed (no SA_RESETHAND): a second signal while the checkpoint is being
    // written only sets the flag again, it never kills the rank half-way.
    for (int s : {SIGTERM, SIGUSR1, SIGINT, SIGHUP}) sigaction(s, &action, nullptr);
}

int stopSignalReceived() { return gSignal; }

const char* signalName(int signal) {
    switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
    }
}

}  // namespace shapevo
