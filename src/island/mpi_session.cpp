// MpiSession: MPI_Init_thread(FUNNELED) when launched by a launcher; thin collective wrappers,
// non-blocking calls completed by politeWait (no busy core while waiting).
#include "island/mpi_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include <mpi.h>
#include <unistd.h>

#include <csignal>

#include "island/launcher_link.hpp"
#include "island/launcher_watch.hpp"
#include "island/polite_wait.hpp"

namespace shapevo {

bool launchedByMpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"})
        if (std::getenv(v)) return true;
    return false;
}

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

WaitTimer::WaitTimer(const MpiSession& mpi) : mpi_(mpi), start_(now()) {}
WaitTimer::~WaitTimer() { mpi_.addWaited(now() - start_); }

MpiSession::MpiSession(int& argc, char**& argv) {
    if (!launchedByMpi()) return;
    // The launcher is the parent now; one that dies before MPI_Init makes MPI_Init fail.
    const pid_t launcher = ::getppid();
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    active_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    std::signal(SIGPIPE, SIG_IGN);
    takeOverLauncherLoss();
    watch_ = std::make_unique<LauncherWatch>(launcher);
}

MpiSession::~MpiSession() {
    if (!active_) return;
    const bool launcherLost = watch_->launcherLost();
    watch_.reset();  // once the launcher is lost, its deadline still holds while the process ends
    if (!launcherLost) MPI_Finalize();
}

bool MpiSession::allTrue(bool ok) const {
    if (!active_) return ok;
    int in = ok ? 1 : 0, out = 0;
    MPI_Request r;
    MPI_Iallreduce(&in, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    return out == 1;
}

bool MpiSession::anyTrue(bool flag) const {
    if (!active_) return flag;
    int in = flag ? 1 : 0, out = 0;
    MPI_Request r;
    MPI_Iallreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    return out == 1;
}

void MpiSession::sum(std::vector<double>& values) const {
    if (!active_) return;
    MPI_Request r;
    MPI_Iallreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
}

void MpiSession::max(std::vector<double>& values) const {
    if (!active_) return;
    MPI_Request r;
    MPI_Iallreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
}

std::pair<double, int> MpiSession::maxLoc(double value) const {
    if (!active_) return {value, 0};
    struct {
        double value;
        int rank;
    } in{value, rank_}, out{};
    MPI_Request r;
    MPI_Iallreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MAXLOC, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    return {out.value, out.rank};
}

std::vector<std::uint32_t> MpiSession::transfer(const std::vector<std::uint32_t>& words, int from, int to) const {
    if (!active_ || from == to) return words;
    constexpr int kTag = 71;
    if (rank_ == from) {
        MPI_Request r;
        MPI_Isend(words.data(), int(words.size()), MPI_UINT32_T, to, kTag, MPI_COMM_WORLD, &r);
        politeWait(*this, r);
    } else if (rank_ == to) {
        MPI_Status status;
        politeProbe(*this, from, kTag, status);
        int count = 0;
        MPI_Get_count(&status, MPI_UINT32_T, &count);
        std::vector<std::uint32_t> out(static_cast<std::size_t>(count));
        MPI_Recv(out.data(), count, MPI_UINT32_T, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        return out;
    }
    return {};
}

bool MpiSession::fromRoot(bool flag) const {
    if (!active_) return flag;
    int v = flag ? 1 : 0;
    MPI_Request r;
    MPI_Ibcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    return v == 1;
}

std::string MpiSession::broadcast(const std::string& s) const {
    if (!active_) return s;
    unsigned long long n = s.size();
    MPI_Request r;
    MPI_Ibcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    std::string out = rank_ == 0 ? s : std::string(n, '\0');
    MPI_Ibcast(out.data(), int(n), MPI_CHAR, 0, MPI_COMM_WORLD, &r);
    politeWait(*this, r);
    return out;
}

void MpiSession::abort(int code) const {
    if (active_) MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);
}

}  // namespace shapevo
