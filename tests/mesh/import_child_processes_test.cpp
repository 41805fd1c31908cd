// Mesh imports leave no process behind, in a process that has other children of its own: readMesh
// and sandboxedCall reap the child they forked (whether it finished, crashed, was stopped at the
// time limit or sent an error) and only that child. Regression for fuzz_mesh_import, whose check
// "no child at all" (waitpid(-1, WNOHANG) failing with ECHILD) broke as soon as the sanitizer
// runtime had started its llvm-symbolizer child (the first time libFuzzer printed NEW_FUNC): the
// check is now "no child that was not there before the import" (tests/child_processes.hpp).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <thread>

#include "cube_mesh.hpp"
#include "mesh_files.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/sandboxed_call.hpp"
#include "../child_processes.hpp"
#include "../test_support.hpp"

namespace shapevo {
namespace {

using test::ChildProcessWatch;
using test::TempDir;
using test::writeFile;

/// A child process that waits until it is killed (as the sanitizer's llvm-symbolizer waits for
/// addresses); the destructor kills and reaps it.
class BystanderChild {
public:
    BystanderChild() : pid_(::fork()) {
        if (pid_ == 0) {
            for (;;) ::pause();
        }
    }
    ~BystanderChild() {
        if (pid_ <= 0) return;
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    BystanderChild(const BystanderChild&) = delete;
    BystanderChild& operator=(const BystanderChild&) = delete;
    pid_t pid() const { return pid_; }
    /// Still this process's child, neither ended nor reaped by someone else.
    bool running() const { return ::waitpid(pid_, nullptr, WNOHANG) == 0; }

private:
    pid_t pid_;
};

meshio::SandboxLimits quickSandbox() {
    meshio::SandboxLimits l;
    l.seconds = 0.3;
    l.memoryBytes = 256ull << 20;
    l.maxOutputBytes = 1 << 20;
    return l;
}

TEST(ImportChildProcesses, WatchSeesARunningChildAndAnUnreapedOneButNotOlderOnes) {
    const BystanderChild older;
    ASSERT_GT(older.pid(), 0);
    const ChildProcessWatch watch;
    EXPECT_TRUE(watch.newChildren().empty());
    const BystanderChild running;
    ASSERT_GT(running.pid(), 0);
    EXPECT_EQ(watch.newChildren(), std::vector<pid_t>{running.pid()});
    const pid_t ended = ::fork();
    if (ended == 0) ::_exit(0);
    ASSERT_GT(ended, 0);
    siginfo_t info{};
    ASSERT_EQ(::waitid(P_PID, id_t(ended), &info, WEXITED | WNOWAIT), 0);  // a zombie now, not reaped
    const std::vector<pid_t> found = watch.newChildren();
    EXPECT_NE(std::find(found.begin(), found.end(), ended), found.end()) << "an unreaped child counts";
    ASSERT_EQ(::waitpid(ended, nullptr, 0), ended);
    EXPECT_EQ(watch.newChildren(), std::vector<pid_t>{running.pid()});
}

TEST(ImportChildProcesses, ImportsBesideAnotherChildLeaveNoneBehindAndReapOnlyTheirOwn) {
    const BystanderChild bystander;  // stands for the sanitizer runtime's llvm-symbolizer
    ASSERT_GT(bystander.pid(), 0);
    const ChildProcessWatch watch;
    TempDir dir;
    // Finished: a mesh comes back.
    const std::string cube = writeFile(dir, "cube.off", test::toOff(test::cubeMesh(1.0f)));
    EXPECT_EQ(readMesh(cube).triangles.size(), 12u);
    // Assimp's error message comes back.
    const std::string junk = writeFile(dir, "junk.off", "OFF\nnot a mesh\n");
    EXPECT_THROW(readMesh(junk), InputError);
    EXPECT_TRUE(watch.newChildren().empty());
    // Crashed, failed, stopped at the time limit.
    const auto crashed = meshio::sandboxedCall([]() -> std::string { std::abort(); }, quickSandbox());
    EXPECT_EQ(crashed.outcome, meshio::SandboxResult::Outcome::Crashed);
    const auto failed = meshio::sandboxedCall([]() -> std::string { throw 7; }, quickSandbox());
    EXPECT_EQ(failed.outcome, meshio::SandboxResult::Outcome::Failed);
    const auto hung = meshio::sandboxedCall(
        []() -> std::string {
            for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        },
        quickSandbox());
    EXPECT_EQ(hung.outcome, meshio::SandboxResult::Outcome::TimedOut);
    EXPECT_TRUE(watch.newChildren().empty()) << "an import process was left behind";
    EXPECT_TRUE(bystander.running()) << "an import reaped (or killed) a child that was not its own";
}

}  // namespace
}  // namespace shapevo
