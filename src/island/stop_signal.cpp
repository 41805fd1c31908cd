// Stop signals: an async-signal-safe flag set by the handler, read once per generation.
#include "island/stop_signal.hpp"

#include <csignal>

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
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGUSR1, &action, nullptr);
}

int stopSignalReceived() { return gSignal; }

const char* signalName(int signal) {
    switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1";
    default: return "a signal";
    }
}

}  // namespace shapevo
