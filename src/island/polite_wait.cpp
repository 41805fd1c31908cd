// politeWait: MPI_Test, then sleep with a doubling back-off.
#include "island/polite_wait.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace shapevo {

namespace {
template <class Done>
void waitUntil(const MpiSession& mpi, Done done) {
    WaitTimer wait(mpi);
    auto pause = std::chrono::microseconds(20);
    while (!done()) {
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(1000));
    }
}
}  // namespace

void politeWait(const MpiSession& mpi, MPI_Request& request) {
    waitUntil(mpi, [&] {
        int flag = 0;
        MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
        return flag != 0;
    });
}

void politeWaitBoth(const MpiSession& mpi, MPI_Request& a, MPI_Request& b) {
    waitUntil(mpi, [&] {
        MPI_Request both[2] = {a, b};
        int flag = 0;
        MPI_Testall(2, both, &flag, MPI_STATUSES_IGNORE);
        a = both[0], b = both[1];
        return flag != 0;
    });
}

}  // namespace shapevo
