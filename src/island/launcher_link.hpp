// The rank's link to its launcher through PMIx (OpenMPI's process-management interface, served by
// mpirun, orted or slurmstepd). When that link breaks (the launcher was killed), OpenMPI's default
// is to end the rank at once (exit 195, from its PMIx thread), whatever it is doing, and so no
// checkpoint is written. takeOverLauncherLoss() registers a PMIx handler for that event that
// ends the event's chain, so OpenMPI's abort never runs, and only records the loss;
// LauncherWatch (island/launcher_watch.hpp) sees it and stops the rank cleanly, in bounded time.
// Promise: without PMIx in the build, or when MPI did not start PMIx (another MPI library, no
// launcher), takeOverLauncherLoss() does nothing and returns false; launcherLinkLost() is then
// always false.
#pragma once

namespace shapevo {

/// Call once, after MPI_Init. True if the handler is registered.
bool takeOverLauncherLoss();
/// PMIx reported the loss of the link to the launcher (any thread).
bool launcherLinkLost();

}  // namespace shapevo
