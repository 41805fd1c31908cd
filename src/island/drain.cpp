// drainUntilEveryoneIsDone: take arrivals, then MPI_Ibarrier once this rank's sends are done; the
// waiting between tests is politeWaitUntil's (sleeps with a back-off, no busy core).
#include "island/drain.hpp"

#include <mpi.h>

#include "island/polite_wait.hpp"

namespace shapevo {

void drainUntilEveryoneIsDone(const MpiSession& mpi, const std::function<bool()>& takeOne,
                              const std::function<bool()>& ownSendsDone) {
    MPI_Request barrier = MPI_REQUEST_NULL;
    bool inBarrier = false;
    politeWaitUntil(mpi, [&] {
        while (takeOne()) {
        }
        if (!inBarrier) {
            if (!ownSendsDone()) return false;
            MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
            inBarrier = true;
        }
        int done = 0;
        MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
        return done != 0;
    });
}

}  // namespace shapevo
