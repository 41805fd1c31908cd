// sandboxedCall: fork, limits in the child, a pipe back, poll with a deadline in the parent.
#include "mesh/sandboxed_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>

// Sanitizer builds (tests/fuzz): a report inside the child must end the child only, not make the
// fuzzer's death callback write a crash file for an input the parent handles. Weak, so normal
// builds (where the sanitizer runtime is absent) see a null pointer.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace shapevo::meshio {

namespace {

bool writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

/// Address space the process has mapped now (bytes), or 0 if unknown.
std::uint64_t currentAddressSpace() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    unsigned long long pages = 0;
    const bool ok = std::fscanf(f, "%llu", &pages) == 1;
    std::fclose(f);
    return ok ? pages * std::uint64_t(::sysconf(_SC_PAGESIZE)) : 0;
}

[[noreturn]] void runChild(const std::function<std::string()>& work, const SandboxLimits& limits, int fd,
                           pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(120);  // the parent died before prctl
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
    for (int s : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGTRAP, SIGSYS, SIGPIPE, SIGXCPU}) std::signal(s, SIG_DFL);
    sigset_t all;
    sigemptyset(&all);
    ::sigprocmask(SIG_SETMASK, &all, nullptr);
    const int null = ::open("/dev/null", O_RDWR);
    if (null >= 0)
        for (int target : {0, 1, 2}) ::dup2(null, target);
    rlimit core{0, 0};
    ::setrlimit(RLIMIT_CORE, &core);
    if (const std::uint64_t now = currentAddressSpace(); now > 0) {
        rlimit as{};
        if (::getrlimit(RLIMIT_AS, &as) == 0) {
            const rlim_t want = rlim_t(now + limits.memoryBytes);
            if (as.rlim_max == RLIM_INFINITY || want < as.rlim_max) as.rlim_cur = want;
            ::setrlimit(RLIMIT_AS, &as);
        }
    }
    rlimit cpu{};
    cpu.rlim_cur = cpu.rlim_max = rlim_t(limits.seconds) + 2;  // belt and braces: the parent kills on time
    ::setrlimit(RLIMIT_CPU, &cpu);
    std::string bytes;
    try {
        bytes = work();
    } catch (...) {
        ::_exit(121);
    }
    ::_exit(writeAll(fd, bytes.data(), bytes.size()) ? 0 : 122);
}

/// Blocks until `pid` has ended; fills in how.
void reap(pid_t pid, SandboxResult& r) {
    int status = 0;
    pid_t got;
    do got = ::waitpid(pid, &status, 0);
    while (got < 0 && errno == EINTR);
    if (got != pid) return;  // ECHILD: someone ignores SIGCHLD; nothing more to learn
    if (WIFSIGNALED(status)) {
        r.signal = WTERMSIG(status);
        if (r.outcome == SandboxResult::Outcome::Finished) r.outcome = SandboxResult::Outcome::Crashed;
    } else if (WIFEXITED(status)) {
        r.exitCode = WEXITSTATUS(status);
        if (r.outcome == SandboxResult::Outcome::Finished && r.exitCode != 0) r.outcome = SandboxResult::Outcome::Failed;
    }
}

}  // namespace

SandboxResult sandboxedCall(const std::function<std::string()>& work, const SandboxLimits& limits) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    const pid_t parent = ::getpid();
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        ::close(fds[0]), ::close(fds[1]);
        throw std::runtime_error(std::string("fork: ") + std::strerror(e));
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(work, limits, fds[1], parent);
    }
    ::close(fds[1]);

    SandboxResult r;
    r.outcome = SandboxResult::Outcome::Finished;
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(limits.seconds));
    char buffer[1 << 16];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            r.outcome = SandboxResult::Outcome::TimedOut;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left, 1000)));
        if (ready < 0 && errno != EINTR) {  // cannot happen with a valid fd
            r.outcome = SandboxResult::Outcome::Failed;
            break;
        }
        if (ready <= 0) continue;
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) break;  // end of file: the child closed its end (exited)
        if (r.output.size() + std::size_t(n) > limits.maxOutputBytes) {
            r.outcome = SandboxResult::Outcome::OutputTooLarge;
            break;
        }
        r.output.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    if (r.outcome != SandboxResult::Outcome::Finished) {
        ::kill(pid, SIGKILL);
        r.output.clear();
    }
    reap(pid, r);
    if (r.outcome != SandboxResult::Outcome::Finished) r.output.clear();
    return r;
}

std::string describeFailure(const SandboxResult& r, const SandboxLimits& limits) {
    switch (r.outcome) {
        case SandboxResult::Outcome::Finished: return "finished";
        case SandboxResult::Outcome::Failed:
            return "it stopped with exit code " + std::to_string(r.exitCode) + " (out of memory: over " +
                   std::to_string(limits.memoryBytes >> 20) + " MiB, or an internal error)";
        case SandboxResult::Outcome::Crashed: {
            const char* name = ::strsignal(r.signal);
            return "it crashed (signal " + std::to_string(r.signal) + (name ? std::string(", ") + name : "") + ")";
        }
        case SandboxResult::Outcome::TimedOut: {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%g", limits.seconds);
            return std::string("it was still running after ") + seconds + " s and was stopped";
        }
        case SandboxResult::Outcome::OutputTooLarge:
            return "its result was larger than " + std::to_string(limits.maxOutputBytes >> 20) + " MiB";
    }
    return "unknown failure";
}

}  // namespace shapevo::meshio
