// politeWait: complete a non-blocking MPI request without keeping a core busy. OpenMPI's blocking
// calls poll in a loop; with more ranks than cores (4 islands on a 2-core laptop, an
// oversubscribed node) a waiting rank then takes the core from the very rank it waits for, and
// lock-step runs collapse. Here the wait tests the request in a loop for up to 100
// microseconds (yielding the core between tests; a non-blocking collective progresses only inside
// MPI calls), then sleeps between tests, from 20 microseconds doubling up to 250: a short wait
// costs what MPI's own does, a long one leaves the core to the others.
// Promise: returns only when the request is complete; adds its time to the session's waiting.
#pragma once
#include <mpi.h>

#include <functional>

#include "island/mpi_session.hpp"

namespace shapevo {

void politeWait(const MpiSession& mpi, MPI_Request& request);
/// Until done() is true, testing it as politeWait tests a request (done() must make MPI progress
/// if it waits on MPI, e.g. by testing requests).
void politeWaitUntil(const MpiSession& mpi, const std::function<bool()>& done);
/// Until a message from `source` with `tag` has arrived (MPI_Iprobe); its status in `status`.
void politeProbe(const MpiSession& mpi, int source, int tag, MPI_Status& status);

}  // namespace shapevo
