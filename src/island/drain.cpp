// drainUntilEveryoneIsDone: take arrivals, then MPI_Ibarrier once this rank's sends are done.
#include "island/drain.hpp"

#include <mpi.h>

#include <chrono>
#include <thread>

namespace shapevo {

void drainUntilEveryoneIsDone(const MpiSession& mpi, const std::function<bool()>& takeOne,
                              const std::function<bool()>& ownSendsDone) {
    WaitTimer wait(mpi);
    MPI_Request barrier = MPI_REQUEST_NULL;
    bool inBarrier = false;
    for (;;) {
        if (takeOne()) continue;
        if (!inBarrier) {
            if (ownSendsDone()) {
                MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
                inBarrier = true;
            }
        } else {
            int done = 0;
            MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
            if (done) return;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(100));  // leave the core to the others
    }
}

}  // namespace shapevo
