// AsyncControl: statuses (tag 73, ranks -> 0) and orders (tag 74, 0 -> ranks) as non-blocking
// sends of a few doubles; receivers probe with MPI_Iprobe and never block.
#include "island/async_control.hpp"

#include <mpi.h>

#include "island/drain.hpp"

namespace shapevo {

namespace {
constexpr int kStatusTag = 73, kOrderTag = 74;
constexpr int kStatusLength = int(sizeof(IslandStatus) / sizeof(double));
static_assert(sizeof(IslandStatus) == kStatusLength * sizeof(double), "IslandStatus is a row of doubles");
}  // namespace

AsyncControl::AsyncControl(const MpiSession& mpi, double cadenceSeconds)
    : mpi_(mpi), cadence_(cadenceSeconds), known_(std::size_t(mpi.size())), heard_(std::size_t(mpi.size())),
      heardAny_(std::size_t(mpi.size()), false) {}

void AsyncControl::report(const IslandStatus& s, bool urgent) {
    if (!mpi_.active() || mpi_.rank() == 0) return;
    const auto now = Clock::now();
    if (!urgent && reportedOnce_ && std::chrono::duration<double>(now - lastReport_).count() < cadence_) return;
    sends_.post(&s, kStatusLength, PostedSends::Type::Double, 0, kStatusTag);
    lastReport_ = now;
    reportedOnce_ = true;
}

void AsyncControl::receiveStatuses() {
    if (!mpi_.active()) return;
    for (;;) {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, kStatusTag, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) return;
        IslandStatus s;
        MPI_Recv(reinterpret_cast<double*>(&s), kStatusLength, MPI_DOUBLE, status.MPI_SOURCE, kStatusTag, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        const auto r = std::size_t(status.MPI_SOURCE);
        if (r < known_.size()) {
            known_[r] = s;
            heard_[r] = Clock::now();
            heardAny_[r] = true;
        }
    }
}

void AsyncControl::collect(const IslandStatus& own) {
    known_[0] = own;
    heard_[0] = Clock::now();
    heardAny_[0] = true;
    receiveStatuses();
}

double AsyncControl::ageSeconds(int rank) const {
    if (!heardAny_[std::size_t(rank)]) return -1;
    return std::chrono::duration<double>(Clock::now() - heard_[std::size_t(rank)]).count();
}

bool AsyncControl::heardFromAll() const {
    for (bool h : heardAny_)
        if (!h) return false;
    return true;
}

void AsyncControl::order(const AsyncOrder& o) {
    if (!mpi_.active() || mpi_.rank() != 0) return;
    const double values[3] = {double(o.kind), double(o.signal), double(o.generation)};
    for (int r = 1; r < mpi_.size(); ++r) sends_.post(values, 3, PostedSends::Type::Double, r, kOrderTag);
}

std::optional<AsyncOrder> AsyncControl::poll() {
    if (!mpi_.active() || mpi_.rank() == 0) return std::nullopt;
    int arrived = 0;
    MPI_Iprobe(0, kOrderTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
    if (!arrived) return std::nullopt;
    double v[3] = {0, 0, 0};
    MPI_Recv(v, 3, MPI_DOUBLE, 0, kOrderTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    AsyncOrder o;
    o.kind = v[0] == double(AsyncOrder::Stop) ? AsyncOrder::Stop : AsyncOrder::Checkpoint;
    o.signal = int(v[1]);
    o.generation = std::uint32_t(v[2]);
    return o;
}

void AsyncControl::finish() {
    if (!mpi_.active() || mpi_.size() < 2) return;
    drainUntilEveryoneIsDone(
        mpi_,
        [&] {  // rank 0 discards statuses that come too late; orders were all taken before
            if (mpi_.rank() != 0) return false;
            int arrived = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, kStatusTag, MPI_COMM_WORLD, &arrived, &status);
            if (!arrived) return false;
            double sink[kStatusLength];
            MPI_Recv(sink, kStatusLength, MPI_DOUBLE, status.MPI_SOURCE, kStatusTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            return true;
        },
        [&] { return sends_.allComplete(); });
}

}  // namespace shapevo
