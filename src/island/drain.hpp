// drainUntilEveryoneIsDone: how async islands end without a deadlock and without a message left
// in flight at MPI_Finalize. Every rank keeps taking (and usually discarding) what arrives while
// its own non-blocking sends complete; once they have, it joins a non-blocking barrier, and it
// leaves when every rank has joined. A rank therefore never waits on a receiver that has stopped
// listening. Collective; counts its time as waiting; between tests it sleeps as politeWait does
// (island/polite_wait.hpp: from 20 us doubling to 250 us), never keeping a core busy.
#pragma once
#include <functional>

#include "island/mpi_session.hpp"

namespace shapevo {

/// `takeOne`: take one arrived message if there is one (true if it took one);
/// `ownSendsDone`: whether every send this rank posted has completed.
void drainUntilEveryoneIsDone(const MpiSession& mpi, const std::function<bool()>& takeOne,
                              const std::function<bool()>& ownSendsDone);

}  // namespace shapevo
