// Stop signals: an async-signal-safe flag (a lock-free atomic) set by the handler or by
// requestStop, read once per generation.
#include "island/stop_signal.hpp"

#include <atomic>
#include <csignal>
#include <initializer_list>

namespace shapevo {

namespace {
std::atomic<int> gSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the flag is set inside a signal handler");
extern "C" void onStopSignal(int s) { gSignal.store(s); }
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

void requestStop(int signal) { gSignal.store(signal); }

int stopSignalReceived() { return gSignal.load(); }

const char* signalName(int signal) {
    switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    case kLauncherLost: return "the loss of its launcher (mpirun or srun)";
    default: return "a signal";
    }
}

}  // namespace shapevo
