// sandboxedCall: runs a function in a forked child process under a memory and a time limit and
// returns the bytes it produced, so code we cannot make safe (a third-party parser fed a hostile
// file: Assimp) can crash, loop or allocate without taking shapevo down. Linux only (fork, pipe,
// setrlimit, prctl). Used by the Assimp mesh reader (mesh/assimp_reader.cpp).
#pragma once
#include <cstdint>
#include <functional>
#include <string>

namespace shapevo::meshio {

struct SandboxLimits {
    std::uint64_t memoryBytes = 1ull << 30;  ///< address space the child may add to what it inherits
    double seconds = 10.0;                   ///< wall-clock time before the child is killed
    std::uint64_t maxOutputBytes = 1ull << 30;  ///< the child is killed if it writes more
};

struct SandboxResult {
    enum class Outcome {
        Finished,        ///< exited with code 0 after writing `output` in full
        Failed,          ///< exited with another code (`exitCode`): work threw, or ran out of memory
        Crashed,         ///< killed by signal `signal` (a segfault, an abort, ...)
        TimedOut,        ///< still running after `seconds`: killed
        OutputTooLarge,  ///< wrote more than maxOutputBytes: killed
    };
    Outcome outcome = Outcome::Failed;
    int exitCode = 0;
    int signal = 0;
    std::string output;
};

/// Forks; the child (one thread, stdin/stdout/stderr on /dev/null, crash signals at their default
/// action, no core dump, killed with its parent, its address space limited to what it inherited
/// plus limits.memoryBytes) runs `work` and writes what it returns to the parent through a pipe,
/// then leaves with _exit (no atexit handlers, no stdio flush). `work` must not rely on other
/// threads (they do not exist in the child). The parent reads until the child is done or a limit
/// is hit, always reaps the child, and never throws for what the child did.
/// @throw std::runtime_error only if the pipe or the process cannot be made.
SandboxResult sandboxedCall(const std::function<std::string()>& work, const SandboxLimits& limits);

/// "killed by signal 11 (Segmentation fault)"-style text for a SandboxResult that is not Finished.
std::string describeFailure(const SandboxResult& result, const SandboxLimits& limits);

}  // namespace shapevo::meshio
